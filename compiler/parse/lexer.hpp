// The re2c lexer of the rule language (implementation in lexer.re). It tracks
// line and column itself and hands the parser complete symbols.
#pragma once

#include <string>

#include "diag/diagnostics.hpp"
#include "parse/parser.hpp"

namespace rift::grammar {

class Lexer {
 public:
  /// `text` must outlive the lexer; the lexer relies on its terminating NUL.
  Lexer(const std::string& text, int file_id, diag::Diagnostics& diags);

  Parser::symbol_type next();

  /// The `///` doc comment whose last line is just above `line` (its lines
  /// joined by spaces), or an empty string.
  std::string doc_before(int line) const;

 private:
  /// Moves the current position over [token_, cursor_).
  void advance();
  diag::Location token_location() const;
  Parser::symbol_type scan_block_comment();
  Parser::symbol_type lex_error(const std::string& message);
  /// Records one `///` line (token_ .. cursor_).
  void doc_line();

  const char* cursor_;
  const char* limit_;
  const char* marker_ = nullptr;
  const char* token_ = nullptr;
  int file_id_;
  diag::Position pos_;        // position of cursor_
  diag::Position token_pos_;  // position of token_
  diag::Diagnostics& diags_;
  std::string doc_;   // the latest run of consecutive `///` lines
  int doc_line_ = 0;  // line of its last line
};

}  // namespace rift::grammar
