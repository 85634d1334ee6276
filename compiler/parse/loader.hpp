// Reads the files named on the command line and, transitively, their includes.
#pragma once

#include <string>
#include <vector>

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"

namespace rift::parse {

/// Loads and parses every file and include. Unreadable files, include cycles
/// and dimension mismatches become diagnostics.
/// Reads the files and everything they include. An include is looked up
/// next to the including file first, then in each of `include_dirs`.
ast::Program load_program(const std::vector<std::string>& paths, diag::SourceManager& sources,
                          diag::Diagnostics& diags,
                          const std::vector<std::string>& include_dirs = {});

/// Parses in-memory text (tests, fuzzing); includes are resolved on disk.
ast::Program load_text(const std::string& path, const std::string& text,
                       diag::SourceManager& sources, diag::Diagnostics& diags);

}  // namespace rift::parse
