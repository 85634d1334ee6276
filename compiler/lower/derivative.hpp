// Forward-mode differentiation of an interaction's forces with respect to
// the positions and velocities of its pattern's vertices (implicit
// integration, docs/language.md "Derivatives"), as a transformation of the
// interaction's body in the IR (ir/body.hpp).
//
// plan_derivative decides whether the forces can be differentiated: which
// values depend on a position or a velocity ("active"), and whether every
// active subexpression has a derivative; when not, it names the first that
// has none. differentiate then appends to the body's graph, per tangent
// pass, the tangent of every let and force (the product rule, the chain rule
// per built-in), and shares the result with the force computation: a primal
// value a tangent needs is the very node the forces compute, so the renderer
// computes it once (lower/share.hpp). A tangent that is identically zero is
// no node at all, so a pass seeded by positions alone has no trace of the
// lets that only carry velocities.
#pragma once

#include <string>
#include <vector>

#include "ir/body.hpp"
#include "lower/kernel_plan.hpp"

namespace rift::lower {

struct DerivativePlan {
  bool available = false;
  /// When not available: where and why (names the subexpression).
  diag::Location where;
  std::string why;
  /// Kernel-plan slot index of each Jacobian vertex (the vertex slots), in order.
  std::vector<int> vertex_slots;
  /// The forces depend on a position (a velocity) somewhere.
  bool depends_on_x = false;
  bool depends_on_v = false;

  /// The Jacobian vertex (index into vertex_slots) of a kernel slot.
  int vertex_of_slot(int slot) const;
};

/// `declared`: where the interaction is declared (named when it reads no vertex).
DerivativePlan plan_derivative(const ir::Body& body, const KernelPlan& kernel,
                               const diag::Location& declared);

/// What a tangent pass differentiates by: the positions, the velocities, or both
/// (the tangents of the state not seeded are zero).
struct Seed {
  bool x = false;
  bool v = false;
};

/// One tangent pass over a body: the node of the tangent of each let and
/// each force, kNoExpr where it is identically zero. Its leaves are
/// PositionTangent and VelocityTangent nodes (the seed's directions).
struct TangentPass {
  Seed seed;
  std::vector<ir::ExprId> lets;    // per let of the body
  std::vector<ir::ExprId> forces;  // per force of the body
};

/// The body with its tangent passes in one graph, shared as a whole: the
/// primal lets, whens and forces are the body's, and both are rendered by one
/// emit::BodyRenderer.
struct DifferentiatedBody {
  ir::Body body;
  std::vector<TangentPass> passes;  // one per seed, in the order asked
};

/// Requires plan.available.
DifferentiatedBody differentiate(const ir::Body& body, const std::vector<Seed>& seeds);

}  // namespace rift::lower
