#include "ast/expr.hpp"

namespace rift::ast {

ExprPtr make_expr(Expr::Kind kind, const Location& loc) {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->loc = loc;
  return e;
}

}  // namespace rift::ast
