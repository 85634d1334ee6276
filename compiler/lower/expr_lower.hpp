// Lowering of checked expressions (ast::Expr) to the typed IR (ir/expr.hpp):
// names become Let / Param / PackParam nodes, the overload the checks chose
// for each built-in and every int-to-real promotion become explicit, and in a
// force loop, reads become slot reads with positions and velocities as
// Position / Velocity nodes (the integrator's stage arrays).
//
// A call of a `def` is inlined: its parameters stand for the nodes of the
// arguments and its lets for the nodes of their values, so that every pass
// after lowering (sharing, derivatives, rendering) sees plain expressions.
// The node a function's let computes carries its name (`spring_force_d`),
// which the renderer gives the value when it computes it into a local.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ast/expr.hpp"
#include "check/expr_types.hpp"
#include "ir/expr.hpp"
#include "lower/kernel_plan.hpp"
#include "resolve/symbols.hpp"

namespace rift::lower {

class ExprLowering {
 public:
  /// `nodes`: the body's dart names (pattern nodes); fold variables are
  /// appended as they are met. `kernel`: set for a force loop, whose reads go
  /// through the slots it planned. `symbols`: what names refer to (resolve/).
  ExprLowering(ir::Graph& graph, std::vector<std::string>& nodes, const KernelPlan* kernel,
               const resolve::Symbols& symbols, const check::ExprTypes& types);

  /// Lets lowered so far become visible to later expressions.
  void add_let(const ast::Let* let, int index);

  ir::ExprId lower(const ast::Expr& e);
  /// `e` converted to `to` (only int -> real converts).
  ir::ExprId lower_as(const ast::Expr& e, ir::Type to);
  /// The dart a path `node@i@j` stands for (the newest node of that name).
  ir::Place place(const ast::Expr& e) const;

 private:
  ir::ExprId convert(ir::ExprId id, ir::Type to);
  ir::ExprId read(const ast::Expr& e);
  ir::ExprId binary(const ast::Expr& e);
  ir::ExprId call(const ast::Expr& e);
  /// The fold node of `e` (`OP of ...` or `OP E over ...`) before its orbits and body.
  ir::Node fold_node(const ast::Expr& e) const;
  ir::ExprId fold(const ast::Expr& e);
  ir::ExprId over(const ast::Expr& e);
  ir::ExprId inline_call(const ast::Expr& e, const ast::Function& f);
  /// `id`, or, when lowering a let created it (`id >= before`), a copy of it
  /// carrying the let's `name` for the renderer (ir::Node::value_name).
  ir::ExprId named(ir::ExprId id, ir::ExprId before, const std::string& name);
  int node_index(const std::string& name) const;

  ir::Graph& g_;
  std::vector<std::string>& nodes_;
  const KernelPlan* kernel_;
  const resolve::Symbols& symbols_;
  const check::ExprTypes& types_;
  std::map<const ast::Let*, int> lets_;
  /// One per function being inlined, innermost last: what its parameters and
  /// lets stand for. A function's body reads only its own frame.
  struct Frame {
    std::map<const ast::Param*, ir::ExprId> params;
    std::map<const ast::Let*, ir::ExprId> lets;
  };
  std::vector<Frame> frames_;
  /// The lets of the folds being lowered: the node each stands for.
  std::map<const ast::Let*, ir::ExprId> fold_lets_;
};

}  // namespace rift::lower
