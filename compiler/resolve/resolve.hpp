// Name resolution: binds every name of every expression (lets, parameters,
// pack parameters, nodes, embeddings) and every assignment target, and reports
// names that do not exist or cannot be read where they are used.
#pragma once

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"
#include "resolve/symbols.hpp"

namespace rift::resolve {

/// Records the embedding of every assignment and init in `symbols`
/// (Symbols::target); the program is only read.
void resolve_names(const ast::Program& program, Symbols& symbols, diag::Diagnostics& diags);

}  // namespace rift::resolve
