// Source positions. The Bison parser uses Location as its location type, so it
// has the `begin` / `end` members Bison's default location rules expect.
#pragma once

namespace rift::diag {

struct Position {
  int line = 1;
  int column = 1;  // counted in characters (UTF-8 code points), 1-based
};

inline bool operator<(const Position& a, const Position& b) {
  return a.line != b.line ? a.line < b.line : a.column < b.column;
}
inline bool operator==(const Position& a, const Position& b) {
  return a.line == b.line && a.column == b.column;
}

struct Location {
  int file = -1;  // index into the SourceManager; -1 for "no location"
  Position begin;
  Position end;  // one past the last character

  bool valid() const { return file >= 0; }
};

/// The smallest location covering a and b (both from one file).
inline Location span(const Location& a, const Location& b) {
  Location l = a;
  l.end = b.end;
  return l;
}

}  // namespace rift::diag
