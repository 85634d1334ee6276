// Expressions of the rule language as C++ expressions over Eigen fixed-size
// types. Every non-scalar intermediate is materialised in its concrete type,
// so no Eigen expression template outlives its operands.
#pragma once

#include <functional>
#include <string>

#include "ast/expr.hpp"
#include "check/expr_types.hpp"
#include "emit/names.hpp"
#include "resolve/symbols.hpp"

namespace rift::emit {

struct ExprContext {
  /// The C++ expression of the dart a node (or dart variable) stands for.
  std::function<std::string(const std::string& node)> dart;
  std::string args = "args";      // the rule's parameters
  std::string params = "params";  // the pack's parameters
  std::string map = "g";          // the rift::GMap
  /// When set, writes an embedding read (Expr::Kind::Read) instead of
  /// `e_NAME[dart]`: force kernels read through slots cached in the match.
  std::function<std::string(const ast::Expr& read)> read;
  /// What names refer to (resolve/). Constant expressions name nothing and
  /// need none.
  const resolve::Symbols* symbols = nullptr;
  /// The expressions' types (check/): every context has them.
  const check::ExprTypes* types = nullptr;
};

std::string emit_expr(const ast::Expr& e, const ExprContext& ctx);
/// The dart a path `node@i@j` stands for.
std::string emit_dart(const ast::Expr& path, const ExprContext& ctx);
/// `code` (of type `from`) converted to `to` (only int -> real converts).
std::string convert(const std::string& code, ast::Type from, ast::Type to);

}  // namespace rift::emit
