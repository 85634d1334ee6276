#include "diag/diagnostics.hpp"

#include <algorithm>
#include <functional>

namespace rift::diag {

const std::vector<std::string>& known_warnings() {
  static const std::vector<std::string> kNames = {"unused-variable", "unused-parameter",
                                                  "unused-function", "float-equality",
                                                  "import-without-code"};
  return kNames;
}

Diagnostic& Diagnostics::error(const Location& loc, std::string message) {
  list_.push_back(Diagnostic{Severity::Error, loc, std::move(message), {}, {}});
  return list_.back();
}

Diagnostic& Diagnostics::warning(const std::string& name, const Location& loc,
                                 std::string message) {
  if (disabled_.count(name)) {
    scratch_ = Diagnostic{};
    return scratch_;
  }
  list_.push_back(
      Diagnostic{werror_ ? Severity::Error : Severity::Warning, loc, std::move(message), name, {}});
  return list_.back();
}

std::size_t Diagnostics::error_count() const {
  return static_cast<std::size_t>(
      std::count_if(list_.begin(), list_.end(),
                    [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

namespace {

bool is_continuation(unsigned char c) {
  return (c & 0xC0u) == 0x80u;
}

/// The caret line: spaces (tabs kept, so the caret lines up) up to `column`,
/// then '^' and '~' up to `end_column` (exclusive) on the same line.
std::string caret_line(std::string_view line, int column, int end_column) {
  std::string out;
  int col = 1;
  for (std::size_t i = 0; i < line.size() && col < column; ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (is_continuation(c)) continue;
    out += c == '\t' ? '\t' : ' ';
    ++col;
  }
  while (col < column) {
    out += ' ';
    ++col;
  }
  out += '^';
  for (int k = column + 1; k < end_column; ++k)
    out += '~';
  return out;
}

}  // namespace

void Diagnostics::render_one(std::string& out, Severity sev, const Location& loc,
                             const std::string& message, const std::string& warning_name) const {
  const char* label = sev == Severity::Error     ? "error"
                      : sev == Severity::Warning ? "warning"
                                                 : "note";
  if (loc.valid()) {
    out += sources_->file(loc.file).path + ":" + std::to_string(loc.begin.line) + ":" +
           std::to_string(loc.begin.column) + ": ";
  } else {
    out += "riftc: ";
  }
  out += std::string(label) + ": " + message;
  if (!warning_name.empty()) out += " [-W" + warning_name + "]";
  out += '\n';
  if (!loc.valid()) return;
  const std::string_view line = sources_->line_text(loc.file, loc.begin.line);
  out += std::string(line) + '\n';
  const int end = loc.end.line == loc.begin.line ? loc.end.column : loc.begin.column + 1;
  out += caret_line(line, loc.begin.column, end) + '\n';
}

std::string Diagnostics::render() const {
  std::vector<const Diagnostic*> sorted;
  sorted.reserve(list_.size());
  for (const Diagnostic& d : list_)
    sorted.push_back(&d);
  // Stable by construction: diagnostics at the same place keep the order they
  // were reported in, which is their order in list_ (the pointers ascend).
  std::sort(sorted.begin(), sorted.end(), [](const Diagnostic* a, const Diagnostic* b) {
    if (a->loc.file != b->loc.file) return a->loc.file < b->loc.file;
    if (!(a->loc.begin == b->loc.begin)) return a->loc.begin < b->loc.begin;
    return std::less<const Diagnostic*>()(a, b);
  });
  std::string out;
  for (const Diagnostic* d : sorted) {
    render_one(out, d->severity, d->loc, d->message, d->warning_name);
    for (const Note& n : d->notes)
      render_one(out, Severity::Note, n.loc, n.message, {});
  }
  return out;
}

}  // namespace rift::diag
