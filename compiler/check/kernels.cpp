#include "check/kernels.hpp"

#include <map>
#include <set>
#include <string>

namespace rift::check {

namespace {

std::string vertex_orbit_text(int dimension) {
  std::string out = "<";
  for (int d = 1; d <= dimension; ++d) {
    if (d > 1) out += ',';
    out += std::to_string(d);
  }
  out += '>';
  return out;
}

bool is_vertex_orbit(const std::vector<int>& dims, int dimension) {
  if (static_cast<int>(dims.size()) != dimension) return false;
  for (int d : dims) {
    if (d < 1 || d > dimension) return false;
  }
  return true;
}

class KernelChecker {
 public:
  KernelChecker(int dimension, const resolve::Symbols& symbols, diag::Diagnostics& diags)
      : dimension_(dimension), symbols_(symbols), diags_(diags) {}

  void expr(const ast::Expr& e) {
    if (e.kind == ast::Expr::Kind::Fold) {
      diags_.error(e.loc, "'" + e.op + " of ... for each' traverses the map, which an " +
                              "interaction's force loop does not do; compute the value in an init");
      return;
    }
    if (e.kind == ast::Expr::Kind::Collect) {
      diags_.error(e.loc, "'" + e.op + " ... over' traverses the map, which an interaction's " +
                              "force loop does not do; compute the value in an init and read it");
      return;
    }
    const ast::Embedding* embedding = symbols_.binding(e).embedding;
    if (e.kind == ast::Expr::Kind::Read && embedding &&
        (e.name == kPositionEmbedding || e.name == kVelocityEmbedding) &&
        !is_vertex_orbit(embedding->orbit.dims, dimension_) && reported_.insert(e.name).second) {
      diags_
          .error(e.loc, "the integrator holds '" + e.name + "' per vertex: declare it on " +
                            vertex_orbit_text(dimension_) + " to read it in an interaction")
          .notes.push_back({embedding->orbit.loc, "its orbit"});
    }
    for (const auto& a : e.args)
      expr(*a);
  }

  void next_interaction() { reported_.clear(); }

 private:
  int dimension_;
  const resolve::Symbols& symbols_;
  diag::Diagnostics& diags_;
  std::set<std::string> reported_;  // once per embedding and interaction
};

}  // namespace

void check_kernels(const ast::Program& program, const resolve::Symbols& symbols,
                   diag::Diagnostics& diags) {
  KernelChecker kc(program.dimension, symbols, diags);
  for (const ast::File& file : program.files) {
    for (const ast::Interaction& inter : file.interactions) {
      kc.next_interaction();
      for (const auto& l : inter.lets)
        kc.expr(*l.value);
      for (const auto& w : inter.whens)
        kc.expr(*w);
      for (const auto& f : inter.forces)
        kc.expr(*f.value);
      for (const auto& j : inter.jacobians)
        kc.expr(*j.value);
      if (inter.energy) kc.expr(*inter.energy);
    }
  }
}

}  // namespace rift::check

namespace rift::check {

std::string camel_case(std::string_view name) {
  std::string out;
  bool upper = true;
  for (char c : name) {
    if (c == '_') {
      if (upper) out += '_';  // keep runs of underscores: names stay distinct
      upper = true;
      continue;
    }
    out += upper && c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
    upper = false;
  }
  return out;
}

void check_generated_names(const ast::Program& program, const resolve::Symbols& symbols,
                           diag::Diagnostics& diags) {
  std::map<std::string, const ast::Ident*> classes;
  auto add = [&](const ast::Ident& name, const char* suffix) {
    const std::string cpp = camel_case(name.text) + suffix;
    auto [it, fresh] = classes.emplace(cpp, &name);
    if (fresh) return;
    diags
        .error(name.loc, "'" + name.text + "' and '" + it->second->text +
                             "' give the same C++ name '" + cpp + "'; rename one")
        .notes.push_back({it->second->loc, "'" + it->second->text + "' declared here"});
  };
  for (const ast::File& file : program.files) {
    for (const ast::Rule& r : file.rules)
      add(r.name, "Rule");
    for (const ast::Script& sc : file.scripts)
      add(sc.name, "Rule");
    for (const ast::Interaction& i : file.interactions) {
      add(i.name, "Params");  // and ...Kernel, ...Interaction
      const std::string tag = i.name.text + "_first_dart";
      if (i.tagged) {
        if (const ast::Embedding* e = symbols.embedding(tag)) {
          diags
              .error(i.tagged_loc, "a tagged interaction '" + i.name.text +
                                       "' declares the embedding '" + tag +
                                       "', which the pack already has")
              .notes.push_back({e->name.loc, "declared here"});
        }
      }
    }
    for (const ast::Criterion& c : file.criteria)
      add(c.name, "Params");  // and ...Criterion
  }
}

}  // namespace rift::check
