#include "rift/io/text_cursor.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace rift::io {

namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// std::from_chars rejects a leading '+', which Fortran-style writers emit.
std::string_view without_plus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  return text;
}

}  // namespace

std::string quote_text(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < std::min(text.size(), kMax); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if (text.size() > kMax) out += "...";
  out += "'";
  return out;
}

TextCursor::TextCursor(std::string source, std::string_view text, int first_line, char comment)
    : source_(std::move(source)),
      text_(text),
      line_(first_line),
      last_line_(first_line),
      comment_(comment) {
  if (first_line == 1 && text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;
}

void TextCursor::skip_blanks(bool cross_lines) {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (is_blank(c)) {
      ++pos_;
    } else if (c == '\n') {
      if (!cross_lines) return;
      ++pos_;
      ++line_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n')
        ++pos_;
    } else {
      return;
    }
  }
}

Token TextCursor::next() {
  skip_blanks(true);
  if (pos_ >= text_.size()) return {{}, last_line_};
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n')
    ++pos_;
  last_line_ = line_;
  return {text_.substr(start, pos_ - start), line_};
}

Token TextCursor::peek() {
  const std::size_t pos = pos_;
  const int line = line_;
  const int last = last_line_;
  const Token t = next();
  pos_ = pos;
  line_ = line;
  last_line_ = last;
  return t;
}

Token TextCursor::next_on_line() {
  skip_blanks(false);
  if (pos_ >= text_.size() || text_[pos_] == '\n') return {{}, line_};
  return next();
}

void TextCursor::skip_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n')
    ++pos_;
  if (pos_ < text_.size()) {
    ++pos_;
    ++line_;
  }
}

Token TextCursor::take_line() {
  const std::size_t start = pos_;
  while (pos_ < text_.size() && text_[pos_] != '\n')
    ++pos_;
  std::string_view line = text_.substr(start, pos_ - start);
  while (!line.empty() && is_blank(line.back()))
    line.remove_suffix(1);
  while (!line.empty() && is_blank(line.front()))
    line.remove_prefix(1);
  last_line_ = line_;
  const Token t{line, line_};
  if (pos_ < text_.size()) {
    ++pos_;
    ++line_;
  }
  return t;
}

bool TextCursor::at_end() {
  skip_blanks(true);
  return pos_ >= text_.size();
}

Token TextCursor::expect(std::string_view what) {
  const Token t = next();
  if (t.empty()) fail(t.line, "unexpected end of file, expected " + std::string(what));
  return t;
}

double TextCursor::real(std::string_view what) {
  return to_real(expect(what), what);
}

std::int64_t TextCursor::integer(std::string_view what) {
  return to_integer(expect(what), what);
}

std::size_t TextCursor::count(std::string_view what) {
  return to_count(expect(what), what);
}

double TextCursor::to_real(Token token, std::string_view what) const {
  const std::string_view text = without_plus(token.text);
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) {
    fail(token.line, std::string(what) + " " + quote_text(token.text) + " is out of range");
  }
  if (ec != std::errc() || end != text.data() + text.size()) {
    fail(token.line,
         "expected " + std::string(what) + " (a number), found " + quote_text(token.text));
  }
  if (!std::isfinite(value)) {
    fail(token.line, std::string(what) + " " + quote_text(token.text) + " is not a finite number");
  }
  return value;
}

double TextCursor::to_coordinate(Token token, std::string_view what) const {
  const double value = to_real(token, what);
  if (std::abs(value) > kMaxCoordinate) {
    fail(token.line, std::string(what) + " " + quote_text(token.text) +
                         " is beyond +-1e30, the largest coordinate rift accepts (areas and "
                         "volumes would overflow); rescale the mesh");
  }
  return value;
}

double TextCursor::check_coordinate(double value, int line, std::string_view what) const {
  if (!std::isfinite(value)) fail(line, std::string(what) + " is not a finite number");
  if (std::abs(value) > kMaxCoordinate) {
    fail(line, std::string(what) + " (" + std::to_string(value) +
                   ") is beyond +-1e30, the largest coordinate rift accepts (areas and volumes "
                   "would overflow); rescale the mesh");
  }
  return value;
}

std::string_view TextCursor::take_bytes(std::size_t n, std::string_view what) {
  if (text_.size() - pos_ < n) {
    fail(line_, "unexpected end of file in binary data at byte " + std::to_string(pos_) +
                    ", expected " + std::string(what));
  }
  const std::string_view bytes = text_.substr(pos_, n);
  line_ += static_cast<int>(std::count(bytes.begin(), bytes.end(), '\n'));
  last_line_ = line_;
  pos_ += n;
  return bytes;
}

bool TextCursor::skip_past(std::string_view marker) {
  const std::size_t at = text_.find(marker, pos_);
  const std::size_t end = at == std::string_view::npos ? text_.size() : at + marker.size();
  line_ += static_cast<int>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                       text_.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
  last_line_ = line_;
  pos_ = end;
  return at != std::string_view::npos;
}

std::int64_t TextCursor::to_integer(Token token, std::string_view what) const {
  const std::string_view text = without_plus(token.text);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) {
    fail(token.line, std::string(what) + " " + quote_text(token.text) + " is out of range");
  }
  if (ec != std::errc() || end != text.data() + text.size()) {
    fail(token.line,
         "expected " + std::string(what) + " (an integer), found " + quote_text(token.text));
  }
  return value;
}

std::size_t TextCursor::to_count(Token token, std::string_view what) const {
  const std::int64_t value = to_integer(token, what);
  // Dart indices are 32-bit, so no importable mesh has more entries than this.
  constexpr std::int64_t kMaxCount = std::numeric_limits<std::int32_t>::max();
  if (value < 0)
    fail(token.line, std::string(what) + " is negative (" + quote_text(token.text) + ")");
  if (value > kMaxCount) {
    fail(token.line, std::string(what) + " " + quote_text(token.text) + " is too large");
  }
  return static_cast<std::size_t>(value);
}

void TextCursor::fail(int line, const std::string& problem) const {
  throw MeshError(source_, line, problem);
}

}  // namespace rift::io
