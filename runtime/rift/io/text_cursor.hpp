// The lexical layer shared by the text mesh readers: a cursor over a whole
// file that hands out whitespace-separated tokens with their 1-based line, and
// number conversions that fail with a MeshError naming that line, never with a
// std exception. Readers differ in grammar, not in how they split and convert
// text, so line tracking lives here once.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rift/mesh/mesh_data.hpp"
#include "rift/mesh/mesh_error.hpp"

namespace rift::io {

struct Token {
  std::string_view text;  ///< empty at the end of the input
  int line = 0;           ///< 1-based line of the token (of the last token at the end)
  bool empty() const { return text.empty(); }
};

class TextCursor {
 public:
  /// `first_line` numbers the first line of `text`, so that a piece of a larger
  /// file (a VTU data array) reports lines of the file. `comment` starts a
  /// comment that runs to the end of the line ('\0': none). A UTF-8 byte-order
  /// mark at the start of a whole file (first_line 1) is skipped: editors on
  /// Windows write one, and it is not part of the first token.
  TextCursor(std::string source, std::string_view text, int first_line = 1, char comment = '\0');

  const std::string& source() const { return source_; }

  /// The next token, crossing line ends; an empty token at the end of the input.
  Token next();
  /// The next token without consuming it.
  Token peek();
  /// The next token if it is on the current line, else an empty token.
  Token next_on_line();
  /// Drops what is left of the current line.
  void skip_line();
  /// What is left of the current line, without its line end, and moves to the
  /// next line. For line-structured headers (a VTK title may be empty).
  Token take_line();
  /// The next `n` bytes as they are (binary data inside a text file, such as a
  /// binary Gmsh section), or an error naming `what` and the byte offset.
  std::string_view take_bytes(std::size_t n, std::string_view what);
  /// Moves past the next occurrence of `marker`; false (at the end) if none.
  bool skip_past(std::string_view marker);
  /// Bytes from the current position to the end of the input.
  std::size_t bytes_left() const { return text_.size() - pos_; }
  /// Byte offset of the current position, for messages about binary data.
  std::size_t offset() const { return pos_; }
  /// True when only whitespace and comments are left.
  bool at_end();
  /// Line of the last token handed out: where a truncated input is reported.
  int line() const { return last_line_; }

  /// next(), or an error "unexpected end of file, expected <what>".
  Token expect(std::string_view what);
  /// expect() then convert; `what` names the value in messages.
  double real(std::string_view what);
  std::int64_t integer(std::string_view what);
  /// A non-negative integer small enough to be an element or vertex count.
  std::size_t count(std::string_view what);

  /// A finite real ("nan", "inf" and text are errors).
  double to_real(Token token, std::string_view what) const;
  /// A real that is a point coordinate: finite and at most kMaxCoordinate in
  /// magnitude (see mesh_data.hpp).
  double to_coordinate(Token token, std::string_view what) const;
  /// The same check for a coordinate read from binary data at `line`.
  double check_coordinate(double value, int line, std::string_view what) const;
  std::int64_t to_integer(Token token, std::string_view what) const;
  std::size_t to_count(Token token, std::string_view what) const;

  /// Throws MeshError(source, line, problem).
  [[noreturn]] void fail(int line, const std::string& problem) const;

 private:
  void skip_blanks(bool cross_lines);

  std::string source_;
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_;       // line of text_[pos_]
  int last_line_;  // line of the last token returned
  char comment_;
};

/// Quotes a token for a message, shortened if it is long (binary garbage).
std::string quote_text(std::string_view text);

/// Makes room for one more entry of a section whose header announced
/// `announced` entries. The capacity follows the entries actually read (it
/// doubles, from 256, and never passes the announced count): a header that
/// claims billions allocates nothing before its data is there and at most
/// twice what the data holds, and an honest header ends at its exact size.
template <class T>
void grow_for_next_entry(std::vector<T>& entries, std::size_t announced) {
  if (entries.size() < entries.capacity()) return;
  const std::size_t doubled = std::max<std::size_t>(2 * entries.size(), 256);
  entries.reserve(std::max(entries.size() + 1, std::min(doubled, announced)));
}

}  // namespace rift::io
