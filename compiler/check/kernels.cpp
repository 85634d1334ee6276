#include "check/kernels.hpp"

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
  KernelChecker(int dimension, diag::Diagnostics& diags) : dimension_(dimension), diags_(diags) {}

  void expr(const ast::Expr& e) {
    if (e.kind == ast::Expr::Kind::Collect) {
      diags_.error(e.loc, "'" + e.op + " ... over' traverses the map, which an interaction's " +
                              "force loop does not do; compute the value in an init and read it");
      return;
    }
    if (e.kind == ast::Expr::Kind::Read && e.embedding &&
        (e.name == kPositionEmbedding || e.name == kVelocityEmbedding) &&
        !is_vertex_orbit(e.embedding->orbit.dims, dimension_) && reported_.insert(e.name).second) {
      diags_
          .error(e.loc, "the integrator holds '" + e.name + "' per vertex: declare it on " +
                            vertex_orbit_text(dimension_) + " to read it in an interaction")
          .notes.push_back({e.embedding->orbit.loc, "its orbit"});
    }
    for (const auto& a : e.args)
      expr(*a);
  }

  void next_interaction() { reported_.clear(); }

 private:
  int dimension_;
  diag::Diagnostics& diags_;
  std::set<std::string> reported_;  // once per embedding and interaction
};

}  // namespace

void check_kernels(const ast::Program& program, const resolve::Symbols& /*symbols*/,
                   diag::Diagnostics& diags) {
  KernelChecker kc(program.dimension, diags);
  for (const ast::File& file : program.files) {
    for (const ast::Interaction& inter : file.interactions) {
      kc.next_interaction();
      for (const auto& l : inter.lets)
        kc.expr(*l.value);
      for (const auto& w : inter.whens)
        kc.expr(*w);
      for (const auto& f : inter.forces)
        kc.expr(*f.value);
      if (inter.energy) kc.expr(*inter.energy);
    }
  }
}

}  // namespace rift::check
