#include "emit/expr_emit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "check/builtins.hpp"
#include "emit/ir_render.hpp"
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

using ast::Expr;
using ast::Type;

bool scalar(Type t) {
  return t == Type::Int || t == Type::Real;
}

std::string dart_path(const Expr& e, const ExprContext& ctx) {
  std::string d = ctx.dart(e.node);
  for (int h : e.hops)
    d = ctx.map + ".alpha(" + d + ", " + std::to_string(h) + ")";
  return d;
}

class Emitter {
 public:
  explicit Emitter(const ExprContext& ctx) : ctx_(ctx) {}

  Type type_of(const Expr& e) const { return ctx_.types->of(e); }

  std::string expr(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::IntLit:
        return "std::int64_t{" + std::to_string(e.integer) + "}";
      case Expr::Kind::RealLit:
        return real_literal(e.real);
      case Expr::Kind::BoolLit:
        return e.boolean ? "true" : "false";
      case Expr::Kind::Name: {
        const resolve::Binding* b = ctx_.symbols ? &ctx_.symbols->binding(e) : nullptr;
        if (b && b->function) return local_of(*b->function, e.name);
        if (b && b->let) return let_name(e.name);
        if (b && b->param) return ctx_.args + "." + member_name(e.name);
        return ctx_.params + "." + member_name(e.name);
      }
      case Expr::Kind::Read:
        if (ctx_.read) return ctx_.read(e);
        return embedding_var(e.name) + "[" + dart_path(e, ctx_) + "]";
      case Expr::Kind::Collect:
        return "collect_" + e.op + "(" + ctx_.map + ", " + embedding_var(e.name) + ", " +
               dart_path(e, ctx_) + ", " + orbit_code(e.orbit.dims) + ")";
      case Expr::Kind::Unary:
        return unary(e);
      case Expr::Kind::Binary:
        return binary(e);
      case Expr::Kind::Cond: {
        const std::string t = cpp_type(type_of(e));
        return std::string("(") + expr(*e.args[0]) + " ? " + t + "(" + as(*e.args[1], type_of(e)) +
               ") : " + t + "(" + as(*e.args[2], type_of(e)) + "))";
      }
      case Expr::Kind::Index: {
        std::string out = std::string("(") + expr(*e.args[0]) + ")(";
        for (std::size_t k = 1; k < e.args.size(); ++k) {
          if (k > 1) out += ", ";
          out += "static_cast<Eigen::Index>(" + expr(*e.args[k]) + ")";
        }
        return out + ")";
      }
      case Expr::Kind::Call:
        return call(e);
      case Expr::Kind::Fold:
        return fold(e);
    }
    return "0";
  }

 private:
  std::string as(const Expr& e, Type to) {
    // An int literal where a real is wanted is written as a real literal.
    if (e.kind == Expr::Kind::IntLit && to == Type::Real) {
      return real_literal(static_cast<double>(e.integer));
    }
    return convert(expr(e), type_of(e), to);
  }

  /// An immediately invoked lambda: one dart per sub-orbit, the body per dart.
  std::string fold(const Expr& e) {
    const Expr& body = *e.args[0];
    const bool mean = e.op == "mean";
    // Folds nest: each gets its own names, so that no inner one shadows another.
    // Named by nesting depth, not by a running count: sibling folds are
    // separate lambdas and may share names, and the names do not depend on
    // the order in which the compiler that built riftc evaluates operands.
    const std::string id = std::to_string(fold_depth_);
    const FoldNesting nesting(fold_depth_);
    const std::string acc = "acc" + id, n = "n" + id;
    const Type acc_type = e.op == "count" ? Type::Int : type_of(e);
    const std::string t = cpp_type(acc_type);
    std::string init = zero_of(acc_type);
    if (e.op == "min") init = "std::numeric_limits<" + t + ">::max()";
    if (e.op == "max") init = "std::numeric_limits<" + t + ">::lowest()";
    std::string step;
    const std::string value = as(body, acc_type);
    if (e.op == "count") {
      step = "if (" + expr(body) + ") ++" + acc + ";";
    } else if (e.op == "min" || e.op == "max") {
      step = acc + " = std::" + e.op + "<" + t + ">(" + acc + ", " + value + ");";
    } else {
      step = acc + " = " + t + "(" + acc + " + " + value + ");";
    }
    if (mean) step += " ++" + n + ";";
    std::string out = "[&]() { " + t + " " + acc + " = " + init + ";";
    if (mean) out += " std::int64_t " + n + " = 0;";
    out += " " + ctx_.map + ".for_each_sub_orbit(" + dart_path(e, ctx_) + ", " +
           orbit_code(e.outer.dims) + ", " + orbit_code(e.orbit.dims) +
           ", [&]([[maybe_unused]] rift::Dart " + ctx_.dart(e.var) +
           ") { rift::throw_if_interrupted(); " + step + " });";
    if (mean) {
      out += " return " + n + " > 0 ? " + t + "(" + acc + " / static_cast<rift::Real>(" + n +
             ")) : " + t + "(" + zero_of(acc_type) + ");";
    } else {
      out += " return " + acc + ";";
    }
    return out + " }()";
  }

  static std::string zero_of(Type t) {
    switch (t) {
      case Type::Vec3:
        return "rift::Vec3::Zero()";
      case Type::Mat3:
        return "rift::Mat3::Zero()";
      case Type::Int:
        return "std::int64_t{0}";
      default:
        return "rift::Real(0)";
    }
  }

  std::string unary(const Expr& e) {
    if (e.op == "not") return "(!" + expr(*e.args[0]) + ")";
    if (scalar(type_of(e))) return "(-" + expr(*e.args[0]) + ")";
    return cpp_type(type_of(e)) + "(-" + expr(*e.args[0]) + ")";
  }

  std::string binary(const Expr& e) {
    const Expr& a = *e.args[0];
    const Expr& b = *e.args[1];
    const std::string& op = e.op;
    if (op == "and" || op == "or") {
      return std::string("(") + expr(a) + (op == "and" ? " && " : " || ") + expr(b) + ")";
    }
    // Scalars meet in a common type; next to a vector or matrix they are reals.
    Type ta = type_of(a), tb = type_of(b);
    if (scalar(ta) && scalar(tb)) {
      const Type common = ta == Type::Real || tb == Type::Real ? Type::Real : Type::Int;
      return std::string("(") + as(a, common) + " " + op + " " + as(b, common) + ")";
    }
    const std::string lhs = scalar(ta) ? as(a, Type::Real) : expr(a);
    const std::string rhs = scalar(tb) ? as(b, Type::Real) : expr(b);
    if (op == "==" || op == "!=") return "(" + lhs + " " + op + " " + rhs + ")";
    return cpp_type(type_of(e)) + "(" + lhs + " " + op + " " + rhs + ")";
  }

  /// A parameter or a let of a function, in the lambda a call renders:
  /// prefixed with the function's name, so that nested calls shadow nothing.
  static std::string local_of(const ast::Function& f, const std::string& name) {
    return f.name.text + "_" + name;
  }

  /// A call of a `def`, as an immediately invoked lambda taking the
  /// arguments as parameters (the force loops inline calls in the IR
  /// instead, lower/expr_lower.cpp).
  std::string function_call(const Expr& e, const ast::Function& f) {
    std::string out = "[&](";
    for (std::size_t k = 0; k < f.params.size(); ++k) {
      const ast::Param& p = f.params[k];
      out += std::string(k ? ", " : "") + (p.uses == 0 ? "[[maybe_unused]] " : "") + "const " +
             cpp_type(p.type) + " " + local_of(f, p.name.text);
    }
    out += ") -> " + cpp_type(f.result) + " {";
    for (const ast::Let& let : f.lets) {
      out += " const " + cpp_type(type_of(*let.value)) + " " + local_of(f, let.name.text) + " = " +
             expr(*let.value) + ";";
    }
    out += " return " + as(*f.value, f.result) + "; }(";
    for (std::size_t k = 0; k < e.args.size(); ++k)
      out += std::string(k ? ", " : "") + as(*e.args[k], f.params[k].type);
    return out + ")";
  }

  std::string call(const Expr& e) {
    if (ctx_.symbols) {
      if (const ast::Function* f = ctx_.symbols->binding(e).function) return function_call(e, *f);
    }
    std::vector<Type> types;
    types.reserve(e.args.size());
    for (const auto& a : e.args)
      types.push_back(type_of(*a));
    const check::Signature* sig = check::select_overload(*check::builtin(e.name), types);
    std::vector<std::string> x;
    x.reserve(e.args.size());
    for (std::size_t k = 0; k < e.args.size(); ++k)
      x.push_back(as(*e.args[k], sig->params[k]));
    const std::string& f = e.name;
    auto join = [&] {
      std::string out;
      for (std::size_t k = 0; k < x.size(); ++k)
        out += (k ? ", " : "") + x[k];
      return out;
    };
    if (f == "vec3") return "rift::Vec3(" + join() + ")";
    if (f == "mat3") return "(rift::Mat3() << " + join() + ").finished()";
    if (f == "stop_gradient") return x[0];
    if (f == "identity") return "rift::Mat3(rift::Mat3::Identity())";
    if (f == "real") return "static_cast<rift::Real>(" + x[0] + ")";
    if (f == "int") return "static_cast<std::int64_t>(" + x[0] + ")";
    if (f == "min" || f == "max" || f == "clamp") {
      return "std::" + f + "<" + cpp_type(sig->result) + ">(" + join() + ")";
    }
    if (f == "abs" && sig->result == Type::Int) return "std::abs(" + x[0] + ")";
    if (f == "dot") return "(" + x[0] + ").dot(" + x[1] + ")";
    if (f == "cross") return "rift::Vec3((" + x[0] + ").cross(" + x[1] + "))";
    if (f == "norm") return "(" + x[0] + ").norm()";
    if (f == "normalize") return "rift::Vec3((" + x[0] + ").normalized())";
    if (f == "outer") return "rift::Mat3((" + x[0] + ") * (" + x[1] + ").transpose())";
    if (f == "transpose") return "rift::Mat3((" + x[0] + ").transpose())";
    if (f == "inverse") return "rift::Mat3((" + x[0] + ").inverse())";
    if (f == "det") return "(" + x[0] + ").determinant()";
    if (f == "trace") return "(" + x[0] + ").trace()";
    if (f == "rotation") return "polar_rotation(" + x[0] + ")";
    if (f == "max_eigenvalue") return "symmetric_max_eigenvalue(" + x[0] + ")";
    if (f == "max_eigenvector") return "symmetric_max_eigenvector(" + x[0] + ")";
    if (f == "eigenvalues") return "symmetric_eigenvalues(" + x[0] + ")";
    return "std::" + f + "(" + join() +
           ")";  // abs sqrt exp log sin cos tan acos asin atan atan2 pow
  }

  const ExprContext& ctx_;
  int fold_depth_ = 0;  ///< folds enclosing the one being rendered
};

}  // namespace

std::string convert(const std::string& code, Type from, Type to) {
  if (from == Type::Int && to == Type::Real) return "static_cast<rift::Real>(" + code + ")";
  return code;
}

std::string emit_dart(const ast::Expr& path, const ExprContext& ctx) {
  return dart_path(path, ctx);
}

std::string emit_expr(const ast::Expr& e, const ExprContext& ctx) {
  return Emitter(ctx).expr(e);
}

}  // namespace rift::emit
