#include "lower/derivative.hpp"

#include "check/kernels.hpp"

namespace rift::lower {

namespace {

using ast::Expr;

int let_index(const ast::Let* let, const std::vector<ast::Let>& lets) {
  for (std::size_t i = 0; i < lets.size(); ++i)
    if (&lets[i] == let) return static_cast<int>(i);
  return -1;
}

bool is_state_read(const Expr& e) {
  return e.kind == Expr::Kind::Read &&
         (e.name == check::kPositionEmbedding || e.name == check::kVelocityEmbedding);
}

// Builtins whose value has no usable derivative: a rule marks their result
// constant with stop_gradient(...) (the rotation of a polar decomposition
// for co-rotational elements), or gives up implicit integration.
bool without_derivative(const std::string& f) {
  return f == "rotation" || f == "max_eigenvalue" || f == "max_eigenvector" || f == "eigenvalues";
}

struct Analysis {
  const std::vector<ast::Let>& lets;
  std::vector<bool>& active;
  DerivativePlan& out;

  // Records the first subexpression without a derivative.
  void fail(const Expr& e, std::string why) {
    if (!out.why.empty()) return;
    out.where = e.loc;
    out.why = std::move(why);
  }

  // Returns whether e is active; checks the active subexpressions.
  bool visit(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::IntLit:
      case Expr::Kind::RealLit:
      case Expr::Kind::BoolLit:
        return false;
      case Expr::Kind::Name: {
        const int i = e.let ? let_index(e.let, lets) : -1;
        return i >= 0 && active[static_cast<std::size_t>(i)];
      }
      case Expr::Kind::Read:
        if (e.name == check::kPositionEmbedding) out.depends_on_x = true;
        if (e.name == check::kVelocityEmbedding) out.depends_on_v = true;
        return is_state_read(e);
      case Expr::Kind::Call:
        if (e.name == "stop_gradient") {
          visit_quiet(*e.args[0]);  // constant for differentiation, whatever it holds
          return false;
        }
        break;
      default:
        break;
    }
    bool any = false;
    for (const auto& a : e.args)
      any = visit(*a) || any;
    if (!any) return false;
    if (e.kind == Expr::Kind::Call && without_derivative(e.name)) {
      fail(e, "'" + e.name +
                  "(...)' depends on a position or a velocity and has no derivative; wrap it "
                  "in stop_gradient(...) to hold it constant for the Jacobian (co-rotational "
                  "elements hold their rotation so)");
    }
    if (e.kind == Expr::Kind::Fold || e.kind == Expr::Kind::Collect) {
      fail(e,
           "a fold over the map depends on a position or a velocity: its derivative is not "
           "formed");
    }
    // Integer and boolean results are piecewise constant: zero derivative.
    return e.type == ast::Type::Real || e.type == ast::Type::Vec3 || e.type == ast::Type::Mat3;
  }

  // Visits for the dependency flags only (under stop_gradient).
  void visit_quiet(const Expr& e) {
    if (e.kind == Expr::Kind::Read) {
      if (e.name == check::kPositionEmbedding) out.depends_on_x = true;
      if (e.name == check::kVelocityEmbedding) out.depends_on_v = true;
    }
    for (const auto& a : e.args)
      visit_quiet(*a);
  }
};

}  // namespace

bool is_active(const Expr& e, const std::vector<bool>& active_let,
               const std::vector<ast::Let>& lets) {
  switch (e.kind) {
    case Expr::Kind::Name: {
      const int i = e.let ? let_index(e.let, lets) : -1;
      return i >= 0 && active_let[static_cast<std::size_t>(i)];
    }
    case Expr::Kind::Read:
      return is_state_read(e);
    case Expr::Kind::Call:
      if (e.name == "stop_gradient") return false;
      break;
    default:
      break;
  }
  if (e.type != ast::Type::Real && e.type != ast::Type::Vec3 && e.type != ast::Type::Mat3)
    return false;
  for (const auto& a : e.args)
    if (is_active(*a, active_let, lets)) return true;
  return false;
}

DerivativePlan plan_derivative(const ast::Interaction& inter, const KernelPlan& plan) {
  DerivativePlan out;
  for (std::size_t s = 0; s < plan.slots.size(); ++s)
    if (plan.slots[s].vertex) out.vertex_slots.push_back(static_cast<int>(s));
  out.active_let.assign(inter.lets.size(), false);
  Analysis a{inter.lets, out.active_let, out};
  // Lets in source order: each sees the activity of the earlier ones.
  for (std::size_t i = 0; i < inter.lets.size(); ++i)
    out.active_let[i] = a.visit(*inter.lets[i].value);
  // Every let is checked (a force may read any of them), then the forces.
  for (const ast::Assign& f : inter.forces)
    a.visit(*f.value);
  out.available = out.why.empty() && !out.vertex_slots.empty();
  if (out.why.empty() && out.vertex_slots.empty()) {
    out.where = inter.name.loc;
    out.why = "the interaction reads no vertex";
  }
  return out;
}

}  // namespace rift::lower
