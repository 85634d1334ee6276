// Forward-mode differentiation of an interaction's forces with respect to
// the positions and velocities of its pattern's vertices (implicit
// integration, docs/language.md "Derivatives"). This pass decides *what*
// is differentiated: which lets depend on a position or a velocity (are
// "active"), whether the force depends on positions, on velocities, and
// whether every active subexpression has a derivative. The derivative
// rules themselves (product rule, chain rule per builtin) are rendered by
// emit/derivative_emit.cpp, one tangent let per active let, sharing the
// force computation's lets.
//
// Written as a pass over the checked AST (the typed IR of issue 9 was not on
// main yet); its inputs are only types, resolved names and statement order,
// so it ports to the IR unchanged in substance.
#pragma once

#include <string>
#include <vector>

#include "ast/program.hpp"
#include "lower/kernel_plan.hpp"

namespace rift::lower {

struct DerivativePlan {
  bool available = false;
  /// When not available: where and why (names the subexpression).
  diag::Location where;
  std::string why;
  /// Kernel-plan slot index of each Jacobian vertex (the vertex slots), in order.
  std::vector<int> vertex_slots;
  /// Per let of the interaction: depends on a position or a velocity.
  std::vector<bool> active_let;
  bool depends_on_x = false;
  bool depends_on_v = false;
};

/// True for an expression that depends on a position or a velocity, given
/// the activity of the lets.
bool is_active(const ast::Expr& e, const std::vector<bool>& active_let,
               const std::vector<ast::Let>& lets);

DerivativePlan plan_derivative(const ast::Interaction& inter, const KernelPlan& plan);

}  // namespace rift::lower
