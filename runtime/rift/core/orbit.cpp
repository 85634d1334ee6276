#include "rift/core/orbit.hpp"

#include <cctype>

namespace rift {

std::string Orbit::str() const {
  std::string s = "<";
  bool first = true;
  for (int d = 0; d <= kMaxDimension; ++d) {
    if (!contains(d)) continue;
    if (!first) s += ',';
    s += static_cast<char>('0' + d);
    first = false;
  }
  s += '>';
  return s;
}

std::optional<Orbit> Orbit::parse(std::string_view text) {
  std::size_t pos = 0;
  auto skip_spaces = [&] {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos])))
      ++pos;
  };
  skip_spaces();
  if (pos >= text.size() || text[pos] != '<') return std::nullopt;
  ++pos;
  Orbit o;
  bool expect_digit = true;
  bool any = false;
  for (;;) {
    skip_spaces();
    if (pos >= text.size()) return std::nullopt;
    char c = text[pos++];
    if (c == '>') {
      if (any && expect_digit) return std::nullopt;  // trailing comma
      break;
    }
    if (expect_digit && c >= '0' && c <= '0' + kMaxDimension) {
      int d = c - '0';
      if (o.contains(d)) return std::nullopt;  // repeated dimension
      o = o.with(d);
      expect_digit = false;
      any = true;
    } else if (!expect_digit && c == ',') {
      expect_digit = true;
    } else {
      return std::nullopt;
    }
  }
  skip_spaces();
  if (pos != text.size()) return std::nullopt;
  return o;
}

}  // namespace rift
