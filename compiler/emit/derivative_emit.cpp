#include "emit/derivative_emit.hpp"

#include "check/builtins.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

using ast::Expr;
using ast::Type;

// Concatenation through append: GCC 12's -Wrestrict misfires on
// `"literal" + std::string` chains once inlined.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts)
    out.append(p);
  return out;
}

bool scalar(Type t) {
  return t == Type::Int || t == Type::Real;
}

bool differentiable_type(Type t) {
  return t == Type::Real || t == Type::Vec3 || t == Type::Mat3;
}

std::string zero(Type t) {
  switch (t) {
    case Type::Vec3:
      return "rift::Vec3(rift::Vec3::Zero())";
    case Type::Mat3:
      return "rift::Mat3(rift::Mat3::Zero())";
    default:
      return "rift::Real(0)";
  }
}

/// Materialises `code` in the concrete type (no Eigen expression template
/// outlives its operands; scalars stay plain).
std::string typed(Type t, const std::string& code) {
  return cpp_type(t == Type::Int ? Type::Real : t) + "(" + code + ")";
}

class Tangents {
 public:
  explicit Tangents(const TangentContext& ctx) : ctx_(ctx) {}

  // "" when the tangent is identically zero.
  std::string of(const Expr& e) {
    if (!differentiable_type(e.type)) return "";
    switch (e.kind) {
      case Expr::Kind::IntLit:
      case Expr::Kind::RealLit:
      case Expr::Kind::BoolLit:
      case Expr::Kind::Collect:  // active folds are refused by lower/derivative
      case Expr::Kind::Fold:
        return "";
      case Expr::Kind::Name:
        if (!e.let) return "";
        for (std::size_t i = 0; i < ctx_.lets->size(); ++i) {
          if (&(*ctx_.lets)[i] == e.let) {
            return (*ctx_.active_let)[i] ? tangent_name(e.name) : "";
          }
        }
        return "";
      case Expr::Kind::Read:
        if (e.name == "position" || e.name == "velocity") return ctx_.state_tangent(e);
        return "";
      case Expr::Kind::Unary: {
        const std::string ta = of(*e.args[0]);
        return ta.empty() || e.op != "-" ? "" : typed(e.type, "-(" + ta + ")");
      }
      case Expr::Kind::Binary:
        return binary(e);
      case Expr::Kind::Cond: {
        const std::string ta = of(*e.args[1]), tb = of(*e.args[2]);
        if (ta.empty() && tb.empty()) return "";
        return cat({"(", primal(*e.args[0]), " ? ", typed(e.type, or_zero(ta, e.type)), " : ",
                    typed(e.type, or_zero(tb, e.type)), ")"});
      }
      case Expr::Kind::Index: {
        const std::string ta = of(*e.args[0]);
        if (ta.empty()) return "";
        std::string out = "(" + ta + ")(";
        for (std::size_t k = 1; k < e.args.size(); ++k) {
          if (k > 1) out += ", ";
          out += "static_cast<Eigen::Index>(" + primal(*e.args[k]) + ")";
        }
        return out + ")";
      }
      case Expr::Kind::Call:
        return call(e);
    }
    return "";
  }

 private:
  std::string primal(const Expr& e) { return emit_expr(e, *ctx_.primal); }
  // Primal as a real when scalar (integers promote next to reals).
  std::string real(const Expr& e) {
    return cat({"(", convert(primal(e), e.type, scalar(e.type) ? Type::Real : e.type), ")"});
  }
  static std::string or_zero(const std::string& t, Type type) {
    return t.empty() ? zero(type) : "(" + t + ")";
  }

  std::string binary(const Expr& e) {
    const Expr& a = *e.args[0];
    const Expr& b = *e.args[1];
    const std::string ta = of(a), tb = of(b);
    if (ta.empty() && tb.empty()) return "";
    const std::string& op = e.op;
    if (op == "+" || op == "-") {
      if (tb.empty()) return typed(e.type, ta);
      if (ta.empty()) return typed(e.type, op == "-" ? "-(" + tb + ")" : tb);
      return typed(e.type, "(" + ta + ") " + op + " (" + tb + ")");
    }
    if (op == "*") {  // product rule, operand order kept (matrices)
      std::string out;
      if (!ta.empty()) out = "(" + ta + ") * " + real(b);
      if (!tb.empty()) out += (out.empty() ? "" : " + ") + real(a) + " * (" + tb + ")";
      return typed(e.type, out);
    }
    if (op == "/") {  // b is a scalar: d(a/b) = da/b - a db/b²
      const std::string bb = real(b);
      std::string out;
      if (!ta.empty()) out = "(" + ta + ") / " + bb;
      if (!tb.empty()) {
        out +=
            (out.empty() ? "-" : " - ") + real(a) + " * ((" + tb + ") / (" + bb + " * " + bb + "))";
      }
      return typed(e.type, out);
    }
    return "";  // comparisons and logic: boolean, no tangent
  }

  std::string call(const Expr& e) {
    const std::string& f = e.name;
    if (f == "stop_gradient" || f == "identity" || f == "int") return "";
    std::vector<std::string> t, x;
    bool any = false;
    for (const auto& a : e.args) {
      t.push_back(of(*a));
      x.push_back(real(*a));
      any = any || !t.back().empty();
    }
    if (!any) return "";
    auto tz = [&](std::size_t k) {
      return or_zero(t[k], scalar(e.args[k]->type) ? Type::Real : e.args[k]->type);
    };
    const Type r = e.type;
    if (f == "real") return typed(r, t[0]);
    if (f == "vec3") return "rift::Vec3(" + tz(0) + ", " + tz(1) + ", " + tz(2) + ")";
    if (f == "mat3") {
      std::string out = "(rift::Mat3() << ";
      for (std::size_t k = 0; k < t.size(); ++k)
        out += (k ? ", " : "") + tz(k);
      return out + ").finished()";
    }
    if (f == "min" || f == "max") {
      const std::string pick = f == "min" ? " <= " : " >= ";
      return "(" + x[0] + pick + x[1] + " ? " + typed(r, tz(0)) + " : " + typed(r, tz(1)) + ")";
    }
    if (f == "clamp") {
      return "(" + x[0] + " < " + x[1] + " ? " + typed(r, tz(1)) + " : (" + x[0] + " > " + x[2] +
             " ? " + typed(r, tz(2)) + " : " + typed(r, tz(0)) + "))";
    }
    if (f == "abs")
      return "(" + x[0] + " >= 0 ? " + typed(r, tz(0)) + " : " + typed(r, "-" + tz(0)) + ")";
    if (f == "sqrt") return typed(r, tz(0) + " / (2 * std::sqrt" + x[0] + ")");
    if (f == "exp") return typed(r, "std::exp" + x[0] + " * " + tz(0));
    if (f == "log") return typed(r, tz(0) + " / " + x[0]);
    if (f == "sin") return typed(r, "std::cos" + x[0] + " * " + tz(0));
    if (f == "cos") return typed(r, "-std::sin" + x[0] + " * " + tz(0));
    if (f == "tan") return typed(r, tz(0) + " / (std::cos" + x[0] + " * std::cos" + x[0] + ")");
    if (f == "asin") return typed(r, tz(0) + " / std::sqrt(1 - " + x[0] + " * " + x[0] + ")");
    if (f == "acos") return typed(r, "-" + tz(0) + " / std::sqrt(1 - " + x[0] + " * " + x[0] + ")");
    if (f == "atan") return typed(r, tz(0) + " / (1 + " + x[0] + " * " + x[0] + ")");
    if (f == "atan2") {  // atan2(y, x)
      return typed(r, "(" + x[1] + " * " + tz(0) + " - " + x[0] + " * " + tz(1) + ") / (" + x[0] +
                          " * " + x[0] + " + " + x[1] + " * " + x[1] + ")");
    }
    if (f == "pow") {
      if (t[1].empty()) {
        return typed(r, x[1] + " * std::pow(" + x[0] + ", " + x[1] + " - 1) * " + tz(0));
      }
      return typed(r, "std::pow(" + x[0] + ", " + x[1] + ") * (" + tz(0) + " * " + x[1] + " / " +
                          x[0] + " + std::log" + x[0] + " * " + tz(1) + ")");
    }
    if (f == "dot") return typed(r, tz(0) + ".dot" + x[1] + " + " + x[0] + ".dot(" + tz(1) + ")");
    if (f == "cross") {
      return typed(r, tz(0) + ".cross" + x[1] + " + " + x[0] + ".cross(" + tz(1) + ")");
    }
    if (f == "norm") return typed(r, x[0] + ".dot(" + tz(0) + ") / " + x[0] + ".norm()");
    if (f == "normalize") {
      // d(a/|a|) = (da - n (n·da)) / |a|, n = a/|a|
      const std::string n = "rift::Vec3(" + x[0] + ".normalized())";
      return typed(
          r, "(" + tz(0) + " - " + n + " * " + n + ".dot(" + tz(0) + ")) / " + x[0] + ".norm()");
    }
    if (f == "outer") {
      return typed(
          r, tz(0) + " * " + x[1] + ".transpose() + " + x[0] + " * " + tz(1) + ".transpose()");
    }
    if (f == "transpose") return typed(r, tz(0) + ".transpose()");
    if (f == "trace") return typed(r, tz(0) + ".trace()");
    if (f == "inverse") {  // d(A⁻¹) = -A⁻¹ dA A⁻¹
      const std::string inv = "rift::Mat3(" + x[0] + ".inverse())";
      return typed(r, "-" + inv + " * " + tz(0) + " * " + inv);
    }
    if (f == "det") {
      // d det A = Σ_k det(A with column k replaced by dA's): no inverse, so
      // it stays finite for singular A.
      const std::string a = x[0], da = tz(0);
      return typed(r, da + ".col(0).dot(" + a + ".col(1).cross(" + a + ".col(2))) + " + a +
                          ".col(0).dot(" + da + ".col(1).cross(" + a + ".col(2))) + " + a +
                          ".col(0).dot(" + a + ".col(1).cross(" + da + ".col(2)))");
    }
    // rotation and the eigen-solvers are refused by lower/derivative.
    return "";
  }

  const TangentContext& ctx_;
};

}  // namespace

std::string tangent_name(const std::string& let) {
  return "t_" + let_name(let);
}

std::string tangent_expr(const ast::Expr& e, const TangentContext& ctx) {
  return Tangents(ctx).of(e);
}

}  // namespace rift::emit
