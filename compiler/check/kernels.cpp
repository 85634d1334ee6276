#include "check/kernels.hpp"

#include "ast/camel_case.hpp"

#include <map>
#include <set>
#include <string>

namespace rift::check {

namespace {

class KernelChecker {
 public:
  explicit KernelChecker(diag::Diagnostics& diags) : diags_(diags) {}

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
    for (const auto& a : e.args)
      expr(*a);
  }

 private:
  diag::Diagnostics& diags_;
};

}  // namespace

void check_kernels(const ast::Program& program, const resolve::Symbols& /*symbols*/,
                   diag::Diagnostics& diags) {
  KernelChecker kc(diags);
  for (const ast::File& file : program.files) {
    for (const ast::Interaction& inter : file.interactions) {
      for (const auto& l : inter.lets)
        kc.expr(*l.value);
      for (const auto& w : inter.whens)
        kc.expr(*w);
      for (const auto& f : inter.forces)
        kc.expr(*f.value);
      for (const auto& st : inter.stores)
        kc.expr(*st.value);
      for (const auto& acc : inter.accumulations)
        kc.expr(*acc.value);
      for (const auto& j : inter.jacobians)
        kc.expr(*j.value);
      if (inter.energy) kc.expr(*inter.energy);
    }
  }
}

}  // namespace rift::check

namespace rift::check {

void check_generated_names(const ast::Program& program, const resolve::Symbols& symbols,
                           diag::Diagnostics& diags) {
  std::map<std::string, const ast::Ident*> classes;
  auto add = [&](const ast::Ident& name, const char* suffix) {
    const std::string cpp = ast::camel_case(name.text) + suffix;
    auto [it, fresh] = classes.emplace(cpp, &name);
    if (fresh) return;
    diags
        .error(name.loc, "'" + name.text + "' and '" + it->second->text +
                             "' give the same C++ name '" + cpp + "'; rename one")
        .notes.push_back({it->second->loc, "'" + it->second->text + "' declared here"});
  };
  for (const ast::File& file : program.files) {
    // An imported pack's classes live in its own namespace (and are checked
    // when it compiles); its names clash with ours in resolve already.
    if (!file.owner.empty()) continue;
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
