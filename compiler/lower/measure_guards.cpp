#include "lower/measure_guards.hpp"

#include <optional>

namespace rift::lower {

namespace {

using ir::ExprId;
using ir::Node;
using ir::Op;

/// The node a value stands for: through lets to the expression they name.
ExprId through_lets(const ir::Body& body, ExprId id) {
  while (body.graph[id].op == Op::Let && body.graph[id].index >= 0)
    id = body.lets[static_cast<std::size_t>(body.graph[id].index)].value;
  return id;
}

/// The value of a real literal (an integer one promoted), if `id` is one.
std::optional<double> literal_real(const ir::Body& body, ExprId id) {
  const Node& n = body.graph[through_lets(body, id)];
  if (n.op == Op::Literal && n.type == ir::Type::Real) return n.real;
  if (n.op == Op::ToReal) {
    const Node& i = body.graph[n.a];
    if (i.op == Op::Literal && i.type == ir::Type::Int) return static_cast<double>(i.integer);
  }
  return std::nullopt;
}

/// Whether `k op threshold` is false for every threshold the scene may give:
/// a literal threshold, or a parameter whose declared bound excludes k.
/// (Scenes are checked against the bounds before a step: rift::ComponentUse.)
bool always_fails(const ir::Body& body, double k, const std::string& op, ExprId threshold,
                  const std::vector<ast::Param>& params) {
  if (const std::optional<double> t = literal_real(body, threshold)) {
    if (op == ">") return !(k > *t);
    if (op == ">=") return !(k >= *t);
    if (op == "<") return !(k < *t);
    if (op == "<=") return !(k <= *t);
    return false;
  }
  const Node& n = body.graph[through_lets(body, threshold)];
  if (n.op != Op::Param) return false;
  for (const ast::Param& p : params) {
    if (p.name.text != n.name) continue;
    // Positive: threshold > 0; NonNegative: threshold >= 0. Only a lower
    // bound is known, so only `>` and `>=` can be shown to fail.
    if (p.bound == ast::Param::Bound::Positive) return (op == ">" || op == ">=") && k <= 0.0;
    if (p.bound == ast::Param::Bound::NonNegative)
      return (op == ">" && k <= 0.0) || (op == ">=" && k < 0.0);
    return false;
  }
  return false;
}

/// The test a guard makes of `cond`: `norm(v) > 0` (or `l > 0` with
/// `let l = norm(v)`) as `dot(v, v) > 0`, the same truth value for every v
/// (norm is of vec3 only): a sum of squares is positive exactly when its
/// square root is, and NaN fails both.
ExprId cheaper_test(ir::Body& body, ExprId cond) {
  ir::Graph& g = body.graph;
  const Node& n = g[cond];
  if (n.op != Op::Gt) return cond;
  const Node& lhs = g[through_lets(body, n.a)];
  const Node& rhs = g[n.b];
  if (lhs.op != Op::Call || lhs.fn != ir::Builtin::Norm || rhs.op != Op::Literal ||
      rhs.type != ir::Type::Real || rhs.real != 0.0) {
    return cond;
  }
  // Copied out: the references move when the graph grows.
  const ExprId v = lhs.a;
  const ExprId zero = n.b;
  const diag::Location loc = lhs.loc;
  const ExprId squared = g.call(ir::Builtin::Dot, ir::Type::Real, {v, v}, loc);
  return g.binary(Op::Gt, ir::Type::Bool, squared, zero);
}

/// Appends the conjuncts of `cond` in evaluation order: the operands of
/// `and`, also inside a let whose value is an `and`.
void conjuncts(ir::Body& body, ExprId cond, std::vector<ExprId>& out) {
  const Node& n = body.graph[through_lets(body, cond)];
  if (n.op == Op::And) {
    const ExprId a = n.a, b = n.b;  // `n` moves when the graph grows
    conjuncts(body, a, out);
    conjuncts(body, b, out);
    return;
  }
  out.push_back(cheaper_test(body, cond));
}

void guards_of(ir::Body& body, ExprId measure, const std::string& op, ExprId threshold,
               const std::vector<ast::Param>& params, std::vector<ExprId>& out) {
  const Node& n = body.graph[through_lets(body, measure)];
  if (n.op != Op::Cond) return;
  const ExprId cond = n.a, then = n.b, otherwise = n.c;
  const std::optional<double> k = literal_real(body, otherwise);
  if (!k || !always_fails(body, *k, op, threshold, params)) return;
  conjuncts(body, cond, out);
  guards_of(body, then, op, threshold, params, out);
}

}  // namespace

std::vector<ExprId> measure_guards(ir::Body& body, ExprId measure, ExprId threshold,
                                   const std::string& op, const std::vector<ast::Param>& params) {
  std::vector<ExprId> guards;
  guards_of(body, measure, op, threshold, params, guards);
  return guards;
}

}  // namespace rift::lower
