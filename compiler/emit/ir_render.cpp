#include "emit/ir_render.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "emit/expr_emit.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

/// Counts the folds being rendered, one level per fold, for their names.
struct FoldNesting {
  explicit FoldNesting(int& depth) : depth_(depth) { ++depth_; }
  ~FoldNesting() { --depth_; }
  FoldNesting(const FoldNesting&) = delete;
  FoldNesting& operator=(const FoldNesting&) = delete;
  int& depth_;
};

using ir::ExprId;
using ir::Node;
using ir::Op;
using ir::Type;

class Renderer {
 public:
  Renderer(const ir::Graph& g, const RenderContext& ctx) : g_(g), ctx_(ctx) {}

  std::string expr(ExprId id) {
    const Node& n = g_[id];
    switch (n.op) {
      case Op::Literal:
        if (n.type == Type::Bool) return n.boolean ? "true" : "false";
        if (n.type == Type::Int)
          return std::string("std::int64_t{") + std::to_string(n.integer) + "}";
        return real_literal(n.real);
      case Op::Position:
      case Op::Velocity:
      case Op::Read:
        if (ctx_.read) return ctx_.read(n);
        return embedding_var(n.embedding) + "[" + place(n.place) + "]";
      case Op::Param:
        return ctx_.args + "." + member_name(n.name);
      case Op::PackParam:
        return ctx_.params + "." + member_name(n.name);
      case Op::Let:
        return let_name(n.name);
      case Op::Neg:
        return std::string("(-") + expr(n.a) + ")";
      case Op::Not:
        return std::string("(!") + expr(n.a) + ")";
      case Op::ToReal:
        return std::string("static_cast<rift::Real>(") + expr(n.a) + ")";
      case Op::And:
        return std::string("(") + expr(n.a) + " && " + expr(n.b) + ")";
      case Op::Or:
        return std::string("(") + expr(n.a) + " || " + expr(n.b) + ")";
      case Op::Cond: {
        const std::string t = cpp_type(n.type);
        if (n.type == Type::Vec3 || n.type == Type::Mat3) {
          return std::string("(") + expr(n.a) + " ? " + t + "(" + expr(n.b) + ") : " + t + "(" +
                 expr(n.c) + "))";
        }
        return std::string("(") + expr(n.a) + " ? " + expr(n.b) + " : " + expr(n.c) + ")";
      }
      case Op::Index: {
        std::string out = std::string("(") + expr(n.a) + ")(" + index(n.b);
        if (n.c != ir::kNoExpr) out += std::string(", ") + index(n.c);
        return out + ")";
      }
      case Op::Call:
        return call(n);
      case Op::Collect:
        return std::string("collect_") + std::string(ir::aggregate_name(n.aggregate)) + "(" +
               ctx_.map + ", " + embedding_var(n.embedding) + ", " + place(n.place) + ", " +
               orbit_code(n.orbit) + ")";
      case Op::Fold:
        return fold(n);
      default:
        return std::string("(") + expr(n.a) + " " + std::string(ir::op_name(n.op)) + " " +
               expr(n.b) + ")";
    }
  }

 private:
  /// A constant index as a plain number: `(h)(0, 2)`.
  std::string index(ExprId id) {
    const Node& n = g_[id];
    if (n.op == Op::Literal && n.type == Type::Int) return std::to_string(n.integer);
    return expr(id);
  }

  std::string place(const ir::Place& p) {
    std::string d = ctx_.dart(p.node);
    for (int h : p.hops)
      d = ctx_.map + ".alpha(" + d + ", " + std::to_string(h) + ")";
    return d;
  }

  /// An immediately invoked lambda: one dart per sub-orbit, the body per dart.
  std::string fold(const Node& n) {
    const bool mean = n.aggregate == ir::Aggregate::Mean;
    const bool count = n.aggregate == ir::Aggregate::Count;
    // Folds nest: each gets its own names, so that no inner one shadows another.
    // Named by nesting depth, not by a running count: sibling folds are
    // separate lambdas and may share names, and the names do not depend on
    // the order in which the compiler that built riftc evaluates operands.
    const std::string id = std::to_string(fold_depth_);
    const FoldNesting nesting(fold_depth_);
    const std::string acc = std::string("acc") + id, cnt = std::string("n") + id;
    const std::string t = cpp_type(n.type);
    std::string init = zero_of(n.type);
    if (n.aggregate == ir::Aggregate::Min)
      init = std::string("std::numeric_limits<") + t + ">::max()";
    if (n.aggregate == ir::Aggregate::Max)
      init = std::string("std::numeric_limits<") + t + ">::lowest()";
    const std::string value = expr(n.a);
    std::string step;
    if (count) {
      step = std::string("if (") + value + ") ++" + acc + ";";
    } else if (n.aggregate == ir::Aggregate::Min || n.aggregate == ir::Aggregate::Max) {
      step = acc + " = std::" + std::string(ir::aggregate_name(n.aggregate)) + "<" + t + ">(" +
             acc + ", " + value + ");";
    } else {
      step = acc + " += " + value + ";";
    }
    if (mean) step += std::string(" ++") + cnt + ";";
    std::string out = std::string("[&]() { ") + t + " " + acc + " = " + init + ";";
    if (mean) out += std::string(" std::int64_t ") + cnt + " = 0;";
    out += std::string(" ") + ctx_.map + ".for_each_sub_orbit(" + place(n.place) + ", " +
           orbit_code(n.outer) + ", " + orbit_code(n.orbit) + ", [&](rift::Dart " +
           ctx_.dart(n.var) + ") { " + step + " });";
    if (mean) {
      out += std::string(" return ") + cnt + " > 0 ? " + t + "(" + acc +
             " / static_cast<rift::Real>(" + cnt + ")) : " + t + "(" + zero_of(n.type) + ");";
    } else {
      out += std::string(" return ") + acc + ";";
    }
    return out + " }()";
  }

  std::string call(const Node& n) {
    std::vector<std::string> x;
    for (std::size_t k = 0; k < n.arity(); ++k)
      x.push_back(expr(n.operand(k)));
    auto join = [&] {
      std::string out;
      for (std::size_t k = 0; k < x.size(); ++k) {
        if (k) out += ", ";
        out += x[k];
      }
      return out;
    };
    using B = ir::Builtin;
    switch (n.fn) {
      case B::Vec3:
        return std::string("rift::Vec3(") + join() + ")";
      case B::Mat3:
        return std::string("(rift::Mat3() << ") + join() + ").finished()";
      case B::Identity:
        return "rift::Mat3::Identity()";
      case B::StopGradient:
        return x[0];
      case B::Real:
        return std::string("static_cast<rift::Real>(") + x[0] + ")";
      case B::Int:
        return std::string("static_cast<std::int64_t>(") + x[0] + ")";
      case B::Min:
      case B::Max:
      case B::Clamp:
        return std::string("std::") + std::string(ir::builtin_name(n.fn)) + "<" + cpp_type(n.type) +
               ">(" + join() + ")";
      case B::Dot:
        return std::string("(") + x[0] + ").dot(" + x[1] + ")";
      case B::Cross:
        return std::string("(") + x[0] + ").cross(" + x[1] + ")";
      case B::Norm:
        return std::string("(") + x[0] + ").norm()";
      case B::Normalize:
        return std::string("(") + x[0] + ").normalized()";
      case B::Outer:
        return std::string("(") + x[0] + ") * (" + x[1] + ").transpose()";
      case B::Transpose:
        return std::string("(") + x[0] + ").transpose()";
      case B::Inverse:
        return std::string("(") + x[0] + ").inverse()";
      case B::Det:
        return std::string("(") + x[0] + ").determinant()";
      case B::Trace:
        return std::string("(") + x[0] + ").trace()";
      case B::Rotation:
        return std::string("polar_rotation(") + x[0] + ")";
      case B::MaxEigenvalue:
        return std::string("symmetric_max_eigenvalue(") + x[0] + ")";
      case B::MaxEigenvector:
        return std::string("symmetric_max_eigenvector(") + x[0] + ")";
      case B::Eigenvalues:
        return std::string("symmetric_eigenvalues(") + x[0] + ")";
      default:  // abs sqrt exp log sin cos tan acos asin atan atan2 pow
        return std::string("std::") + std::string(ir::builtin_name(n.fn)) + "(" + join() + ")";
    }
  }

  const ir::Graph& g_;
  const RenderContext& ctx_;
  int fold_depth_ = 0;  ///< folds enclosing the one being rendered
};

}  // namespace

std::string real_literal(double v) {
  if (std::isinf(v)) {
    return v > 0 ? "std::numeric_limits<rift::Real>::infinity()"
                 : "(-std::numeric_limits<rift::Real>::infinity())";
  }
  // The shortest decimal that reads back as the same double: 0.1, not 0.10000000000000001.
  char buf[64];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string render(const ir::Graph& g, ir::ExprId id, const RenderContext& ctx) {
  return Renderer(g, ctx).expr(id);
}

}  // namespace rift::emit
