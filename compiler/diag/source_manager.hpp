// Owns the text of every file riftc reads, so diagnostics can quote source lines.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rift::diag {

struct SourceFile {
  std::string path;  // as given on the command line or resolved from an include
  std::string text;
  std::vector<std::size_t> line_starts;  // byte offset of each line
};

class SourceManager {
 public:
  /// Registers a file's text and returns its id.
  int add(std::string path, std::string text);
  /// Reads a file from disk; -1 when it cannot be read.
  int load(const std::string& path);
  /// The id of an already registered path, or -1.
  int find(std::string_view path) const;

  const SourceFile& file(int id) const { return *files_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return files_.size(); }
  /// Line `line` (1-based) of a file without its newline; empty when out of range.
  std::string_view line_text(int id, int line) const;

 private:
  std::vector<std::unique_ptr<SourceFile>> files_;
};

}  // namespace rift::diag
