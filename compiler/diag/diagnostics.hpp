// Diagnostics as data: checks add them, nobody prints until the end, when they
// are sorted by location and rendered with the source line and a caret.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "diag/location.hpp"
#include "diag/source_manager.hpp"

namespace rift::diag {

enum class Severity { Error, Warning, Note };

struct Note {
  Location loc;
  std::string message;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  Location loc;
  std::string message;
  std::string warning_name;  // only for warnings: the NAME of -Wno-NAME
  std::vector<Note> notes;
};

/// The names of every warning riftc knows; -Wno-NAME accepts only these.
const std::vector<std::string>& known_warnings();

class Diagnostics {
 public:
  explicit Diagnostics(const SourceManager& sources) : sources_(&sources) {}

  /// Adds an error; the returned reference lets the caller attach notes.
  Diagnostic& error(const Location& loc, std::string message);
  /// Adds a named warning, or nothing when it is disabled (then returns a scratch
  /// diagnostic so callers can still attach notes).
  Diagnostic& warning(const std::string& name, const Location& loc, std::string message);

  void disable_warning(const std::string& name) { disabled_.insert(name); }
  void set_warnings_as_errors(bool on) { werror_ = on; }

  std::size_t error_count() const;
  bool has_errors() const { return error_count() > 0; }
  const std::vector<Diagnostic>& all() const { return list_; }

  /// Every diagnostic, sorted by file order then position, rendered as text.
  std::string render() const;

 private:
  void render_one(std::string& out, Severity sev, const Location& loc, const std::string& message,
                  const std::string& warning_name) const;

  const SourceManager* sources_;
  std::vector<Diagnostic> list_;
  std::set<std::string> disabled_;
  bool werror_ = false;
  Diagnostic scratch_;
};

}  // namespace rift::diag
