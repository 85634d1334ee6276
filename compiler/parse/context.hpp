// What the Bison actions write into while a file is parsed: the file's AST and
// the declaration currently open (rule, interaction, criterion), so that body
// statements can come in any order.
#pragma once

#include <vector>

#include "ast/decl.hpp"
#include "diag/diagnostics.hpp"

namespace rift::grammar {
class Lexer;
}

namespace rift::parse {

struct ParseContext {
  grammar::Lexer& lexer;
  ast::File& file;
  diag::Diagnostics& diags;

  ast::Rule rule;
  ast::Interaction interaction;
  ast::Criterion criterion;
  ast::Script script;
  ast::Pattern* pattern = nullptr;        // the pattern block being read
  std::vector<ast::Let>* lets = nullptr;  // where `let` goes in the open body
  std::vector<ast::ExprPtr>* whens = nullptr;
  std::vector<ast::BodyStmt>* body = nullptr;  // the source order of both
  bool reported_depth = false;                 // "nested too deeply" is said once per file
  ast::Function function{};                    // the `def` being read
};

/// Deepest expression tree the parser builds: every later pass recurses over
/// expressions, and this keeps their stack use bounded on hostile input.
inline constexpr int kMaxExprDepth = 256;

}  // namespace rift::parse
