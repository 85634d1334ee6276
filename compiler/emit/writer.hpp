// Generated C++ goes through this writer: it owns indentation and counts
// output lines, so `#line` directives can point into the .rules file for an
// expression and back into the generated file afterwards.
#pragma once

#include <string>
#include <string_view>

#include "diag/location.hpp"
#include "diag/source_manager.hpp"

namespace rift::emit {

class Writer {
 public:
  Writer(std::string output_name, const diag::SourceManager& sources)
      : output_name_(std::move(output_name)), sources_(&sources) {}

  void line(std::string_view text = {});
  /// `text` then one more level of indentation ("... {").
  void open(std::string_view text);
  /// One level less, then `text` ("}").
  void close(std::string_view text = "}");
  /// A line between two blocks ("} else {"): one level less for this line only.
  void middle(std::string_view text);
  /// Marks the next line as coming from `loc` in a .rules file.
  void from_source(const diag::Location& loc);
  /// Back to the generated file's own numbering.
  void resume();
  /// Without them (`riftc --no-line-directives`), the output does not change
  /// when a line is added to a .rules file, which keeps it diffable.
  void set_line_directives(bool on) { line_directives_ = on; }

  const std::string& str() const { return out_; }
  /// "file:line:column: " of a location in a .rules file ("" when invalid).
  std::string where(const diag::Location& loc) const;

 private:
  std::string output_name_;
  const diag::SourceManager* sources_;
  std::string out_;
  int indent_ = 0;
  int lines_ = 0;
  bool line_directives_ = true;
};

/// A C++ string literal for `text`.
std::string quote(std::string_view text);

}  // namespace rift::emit
