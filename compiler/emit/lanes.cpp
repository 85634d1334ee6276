#include "emit/lanes.hpp"

namespace rift::emit {

namespace {

using ir::Builtin;
using ir::Node;
using ir::Op;
using ir::Type;

bool lane_type(Type t) {
  return t == Type::Real || t == Type::Vec3 || t == Type::Bool;
}

bool lanes_builtin(const ir::Graph& g, const Node& n) {
  switch (n.fn) {
    case Builtin::Sqrt:
    case Builtin::Abs:
    case Builtin::Min:
    case Builtin::Max:
    case Builtin::Clamp:
    case Builtin::Vec3:
    case Builtin::Dot:
    case Builtin::Cross:
    case Builtin::Norm:
    case Builtin::Normalize:
    case Builtin::StopGradient:
      return true;
    case Builtin::Real:  // of a real only: a conversion from an integer is not a lane value
      return g[n.a].type == Type::Real;
    default:
      return false;
  }
}

/// Whether node `n` (whose operands are checked on their own) has a lanes form.
bool lanes_node(const ir::Graph& g, const Node& n) {
  // An integer only as a constant index of a vec3 (Index checks its operand).
  if (n.type == Type::Int) return n.op == Op::Literal;
  if (!lane_type(n.type)) return false;
  switch (n.op) {
    case Op::Literal:
    case Op::Param:
    case Op::PackParam:
    case Op::Let:
    case Op::Neg:
    case Op::Not:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::And:
    case Op::Or:
    case Op::Cond:
      return true;
    case Op::Position:
    case Op::Velocity:
    case Op::Read:
      // Through the match's slot, not a walk of the map; a column of reals or vec3s.
      return n.place.slot >= 0 && n.type != Type::Bool;
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
    case Op::Eq:
    case Op::Ne:
      return g[n.a].type == Type::Real && g[n.b].type == Type::Real;
    case Op::Index:
      return g[n.a].type == Type::Vec3 && g[n.b].op == Op::Literal && n.c == ir::kNoExpr;
    case Op::Call:
      return lanes_builtin(g, n);
    default:  // ToReal (an integer), Fold, the tangents of derivative passes
      return false;
  }
}

}  // namespace

const char* lanes_type(Type t) {
  if (t == Type::Vec3) return "rift::lanes::Vec3";
  if (t == Type::Bool) return "rift::lanes::Mask";
  return "rift::lanes::Real";  // the only other type a lanes body has
}

bool renders_in_lanes(const ir::Body& b) {
  if (b.forces.empty() || !b.stores.empty()) return false;
  bool ok = true;
  auto check = [&](ir::ExprId root) {
    if (root == ir::kNoExpr) return;
    ir::visit(b.graph, root, [&](const Node& n) { ok = ok && lanes_node(b.graph, n); });
  };
  for (const ir::Stmt& s : b.stmts)
    check(s.kind == ir::Stmt::Kind::When ? s.cond : b.lets[static_cast<std::size_t>(s.let)].value);
  for (const ir::Force& f : b.forces)
    check(f.value);
  return ok;
}

}  // namespace rift::emit
