// Runs the generated parser over one registered source file.
#pragma once

#include "ast/decl.hpp"
#include "diag/diagnostics.hpp"

namespace rift::parse {

/// Parses file `file_id` of the diagnostics' source manager into `out`.
/// Syntax errors are added to `diags`; the AST holds what could be recovered.
void parse_file(const diag::SourceManager& sources, int file_id, diag::Diagnostics& diags,
                ast::File& out);

}  // namespace rift::parse
