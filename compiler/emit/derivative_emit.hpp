// Renders forward-mode derivatives (tangents) of expressions as C++: for an
// expression e and tangents of the positions and velocities it reads, the
// C++ of de, by the differentiation rules of docs/language.md. Which lets
// are active is decided by lower/derivative.*; primal values are the force
// computation's lets (shared, not recomputed) and the tangent of let `l` is
// the variable `t_l`.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ast/decl.hpp"
#include "emit/expr_emit.hpp"

namespace rift::emit {

struct TangentContext {
  const ExprContext* primal = nullptr;  // how primal subexpressions are written
  const std::vector<ast::Let>* lets = nullptr;
  const std::vector<bool>* active_let = nullptr;
  /// The tangent of a position or velocity read (Expr::Kind::Read).
  std::function<std::string(const ast::Expr& read)> state_tangent;
};

/// The C++ of the tangent of e, or "" when it is identically zero.
std::string tangent_expr(const ast::Expr& e, const TangentContext& ctx);

/// The tangent let's variable name for let `name`.
std::string tangent_name(const std::string& let);

}  // namespace rift::emit
