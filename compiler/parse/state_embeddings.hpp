// The simulator's state embeddings (position, velocity, masses, pinned,
// vertex_force, point and element indices) as rift declares them in every
// pack: from the runtime's one table (rift/core/state_embeddings.hpp), as
// rule-language declarations in a source of their own, "<rift state>".
#pragma once

#include <string>

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"

namespace rift::parse {

/// The name of the source that holds the state declarations.
inline constexpr const char* kStateSource = "<rift state>";

/// The declarations, in the rule language, for a pack of `dimension`.
std::string state_embeddings_text(int dimension);

/// Parses the declarations for the program's dimension and appends them as
/// a file marked `builtin`.
void add_state_embeddings(ast::Program& program, diag::SourceManager& sources,
                          diag::Diagnostics& diags);

}  // namespace rift::parse
