#include "ir/expr.hpp"

#include <array>
#include <cstdio>
#include <initializer_list>
#include <utility>

#include "ast/orbit_text.hpp"

namespace rift::ir {

namespace {

constexpr std::array<std::pair<Builtin, std::string_view>, 34> kBuiltins = {{
    {Builtin::Sqrt, "sqrt"},
    {Builtin::Exp, "exp"},
    {Builtin::Log, "log"},
    {Builtin::Sin, "sin"},
    {Builtin::Cos, "cos"},
    {Builtin::Tan, "tan"},
    {Builtin::Acos, "acos"},
    {Builtin::Asin, "asin"},
    {Builtin::Atan, "atan"},
    {Builtin::Atan2, "atan2"},
    {Builtin::Pow, "pow"},
    {Builtin::Abs, "abs"},
    {Builtin::Min, "min"},
    {Builtin::Max, "max"},
    {Builtin::Clamp, "clamp"},
    {Builtin::Real, "real"},
    {Builtin::Int, "int"},
    {Builtin::Vec3, "vec3"},
    {Builtin::Mat3, "mat3"},
    {Builtin::Identity, "identity"},
    {Builtin::Dot, "dot"},
    {Builtin::Cross, "cross"},
    {Builtin::Norm, "norm"},
    {Builtin::Normalize, "normalize"},
    {Builtin::Outer, "outer"},
    {Builtin::Transpose, "transpose"},
    {Builtin::Inverse, "inverse"},
    {Builtin::Det, "det"},
    {Builtin::Trace, "trace"},
    {Builtin::Rotation, "rotation"},
    {Builtin::MaxEigenvalue, "max_eigenvalue"},
    {Builtin::MaxEigenvector, "max_eigenvector"},
    {Builtin::Eigenvalues, "eigenvalues"},
    {Builtin::StopGradient, "stop_gradient"},
}};

constexpr std::array<std::pair<Aggregate, std::string_view>, 5> kAggregates = {{
    {Aggregate::Sum, "sum"},
    {Aggregate::Mean, "mean"},
    {Aggregate::Min, "min"},
    {Aggregate::Max, "max"},
    {Aggregate::Count, "count"},
}};

std::string place_text(const Place& p, const std::vector<std::string>& names) {
  std::string out = p.node >= 0 && static_cast<std::size_t>(p.node) < names.size()
                        ? names[static_cast<std::size_t>(p.node)]
                        : "?";
  for (int h : p.hops) {
    out += '@';
    out += std::to_string(h);
  }
  return out;
}

using ast::orbit_text;

/// Concatenation by appending (GCC 12's -Wrestrict misfires on chains of `"(" + std::string`).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts)
    out += p;
  return out;
}

}  // namespace

std::size_t Node::arity() const {
  if (a == kNoExpr) return 0;
  if (b == kNoExpr) return 1;
  if (c == kNoExpr) return 2;
  return 3 + more.size();
}

ExprId Node::operand(std::size_t k) const {
  if (k == 0) return a;
  if (k == 1) return b;
  if (k == 2) return c;
  return more[k - 3];
}

ExprId Graph::add(Node n) {
  nodes_.push_back(std::move(n));
  return static_cast<ExprId>(nodes_.size() - 1);
}

ExprId Graph::real(double v) {
  Node n;
  n.type = Type::Real;
  n.real = v;
  return add(std::move(n));
}

ExprId Graph::integer(std::int64_t v) {
  Node n;
  n.type = Type::Int;
  n.integer = v;
  return add(std::move(n));
}

ExprId Graph::boolean(bool v) {
  Node n;
  n.type = Type::Bool;
  n.boolean = v;
  return add(std::move(n));
}

ExprId Graph::unary(Op op, Type type, ExprId a) {
  Node n;
  n.op = op;
  n.type = type;
  n.a = a;
  return add(std::move(n));
}

ExprId Graph::binary(Op op, Type type, ExprId a, ExprId b) {
  Node n;
  n.op = op;
  n.type = type;
  n.a = a;
  n.b = b;
  return add(std::move(n));
}

ExprId Graph::call(Builtin fn, Type type, std::vector<ExprId> args, diag::Location loc) {
  Node n;
  n.op = Op::Call;
  n.loc = loc;
  n.fn = fn;
  n.type = type;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (k == 0) n.a = args[k];
    if (k == 1) n.b = args[k];
    if (k == 2) n.c = args[k];
    if (k >= 3) n.more.push_back(args[k]);
  }
  return add(std::move(n));
}

std::string_view builtin_name(Builtin fn) {
  for (const auto& [f, name] : kBuiltins) {
    if (f == fn) return name;
  }
  return "?";
}

bool builtin_from_name(std::string_view name, Builtin& out) {
  for (const auto& [f, n] : kBuiltins) {
    if (n == name) {
      out = f;
      return true;
    }
  }
  return false;
}

std::string_view aggregate_name(Aggregate a) {
  for (const auto& [x, name] : kAggregates) {
    if (x == a) return name;
  }
  return "?";
}

bool aggregate_from_name(std::string_view name, Aggregate& out) {
  for (const auto& [x, n] : kAggregates) {
    if (n == name) {
      out = x;
      return true;
    }
  }
  return false;
}

std::string_view op_name(Op op) {
  switch (op) {
    case Op::Literal:
      return "literal";
    case Op::Position:
      return "position";
    case Op::Velocity:
      return "velocity";
    case Op::Read:
      return "read";
    case Op::Param:
      return "param";
    case Op::PackParam:
      return "pack param";
    case Op::Let:
      return "let";
    case Op::PositionTangent:
      return "tangent of position";
    case Op::VelocityTangent:
      return "tangent of velocity";
    case Op::Neg:
      return "-";
    case Op::Not:
      return "not";
    case Op::ToReal:
      return "real";
    case Op::Add:
      return "+";
    case Op::Sub:
      return "-";
    case Op::Mul:
      return "*";
    case Op::Div:
      return "/";
    case Op::Lt:
      return "<";
    case Op::Le:
      return "<=";
    case Op::Gt:
      return ">";
    case Op::Ge:
      return ">=";
    case Op::Eq:
      return "==";
    case Op::Ne:
      return "!=";
    case Op::And:
      return "and";
    case Op::Or:
      return "or";
    case Op::Cond:
      return "if";
    case Op::Index:
      return "index";
    case Op::Call:
      return "call";
    case Op::Fold:
      return "fold";
  }
  return "?";
}

std::string to_text(const Graph& g, ExprId id, const std::vector<std::string>& node_names) {
  const Node& n = g[id];
  auto sub = [&](ExprId x) { return to_text(g, x, node_names); };
  switch (n.op) {
    case Op::Literal: {
      if (n.type == Type::Bool) return n.boolean ? "true" : "false";
      if (n.type == Type::Int) return std::to_string(n.integer);
      if (n.type == Type::Vec3) return "vec3(0, 0, 0)";
      if (n.type == Type::Mat3) return "(0 * identity())";
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", n.real);
      return buf;
    }
    case Op::Position:
      return place_text(n.place, node_names) + ".position";
    case Op::Velocity:
      return place_text(n.place, node_names) + ".velocity";
    case Op::PositionTangent:
      return "d(" + place_text(n.place, node_names) + ".position)";
    case Op::VelocityTangent:
      return "d(" + place_text(n.place, node_names) + ".velocity)";
    case Op::Read:
      return place_text(n.place, node_names) + "." + n.embedding;
    case Op::Param:
    case Op::PackParam:
    case Op::Let:
      return n.name;
    case Op::Neg:
      return "(-" + sub(n.a) + ")";
    case Op::Not:
      return "(not " + sub(n.a) + ")";
    case Op::ToReal:
      return "real(" + sub(n.a) + ")";
    case Op::Cond:
      return "(if " + sub(n.a) + " then " + sub(n.b) + " else " + sub(n.c) + ")";
    case Op::Index: {
      std::string out = sub(n.a) + "[" + sub(n.b);
      if (n.c != kNoExpr) out += ", " + sub(n.c);
      return out + "]";
    }
    case Op::Call: {
      std::string out = std::string(builtin_name(n.fn)) + "(";
      for (std::size_t k = 0; k < n.arity(); ++k) {
        if (k) out += ", ";
        out += sub(n.operand(k));
      }
      return out + ")";
    }
    case Op::Fold: {
      const std::string var = n.var >= 0 && static_cast<std::size_t>(n.var) < node_names.size()
                                  ? node_names[static_cast<std::size_t>(n.var)]
                                  : "?";
      return cat({"(", aggregate_name(n.aggregate), " of ", sub(n.a), " for each ",
                  orbit_text(n.orbit), "(", var, ") in ", orbit_text(n.outer), "(",
                  place_text(n.place, node_names), "))"});
    }
    default:
      return cat({"(", sub(n.a), " ", op_name(n.op), " ", sub(n.b), ")"});
  }
}

std::vector<int> count_uses(const Graph& g, const std::vector<ExprId>& roots) {
  std::vector<int> uses(g.size(), 0);
  std::vector<bool> seen(g.size(), false);
  std::vector<ExprId> stack;
  for (ExprId r : roots) {
    if (r == kNoExpr) continue;
    ++uses[static_cast<std::size_t>(r)];
    stack.push_back(r);
  }
  while (!stack.empty()) {
    const ExprId id = stack.back();
    stack.pop_back();
    if (seen[static_cast<std::size_t>(id)]) continue;
    seen[static_cast<std::size_t>(id)] = true;
    const Node& n = g[id];
    for (std::size_t k = 0; k < n.arity(); ++k) {
      ++uses[static_cast<std::size_t>(n.operand(k))];
      stack.push_back(n.operand(k));
    }
  }
  return uses;
}

}  // namespace rift::ir
