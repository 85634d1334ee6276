// The type of every expression, as check_types computed it: a side table
// keyed by the expression, so that the AST stays as the parser built it.
// lower/ and emit/ read it; only check_types writes it.
#pragma once

#include <unordered_map>

#include "ast/expr.hpp"

namespace rift::check {

class ExprTypes {
 public:
  /// Type::Error for an expression check_types did not reach or found wrong.
  ast::Type of(const ast::Expr& e) const {
    const auto it = types_.find(&e);
    return it == types_.end() ? ast::Type::Error : it->second;
  }
  void set(const ast::Expr& e, ast::Type t) { types_[&e] = t; }

 private:
  std::unordered_map<const ast::Expr*, ast::Type> types_;
};

}  // namespace rift::check
