// What an interaction's force loop may do: it reads values through slots
// cached at match time, so it may not traverse the map (no collections).
// Positions and velocities come from the integrator's stage arrays, indexed
// by vertex slot: they are state embeddings, always on the vertex orbit
// (parse/state_embeddings.hpp).
#pragma once

#include <string>
#include <string_view>

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"
#include "resolve/symbols.hpp"
#include "rift/core/state_embeddings.hpp"

namespace rift::check {

/// Names the integrator passes as stage arrays (ForceInput::x and ::v), from
/// the one table of the simulator's state embeddings.
inline constexpr std::string_view kPositionEmbedding = state::kPosition;
inline constexpr std::string_view kVelocityEmbedding = state::kVelocity;

void check_kernels(const ast::Program& program, const resolve::Symbols& symbols,
                   diag::Diagnostics& diags);

/// The C++ names the generator derives must be distinct: class names are the
/// rule-language names in CamelCase, and a `tagged` interaction declares an
/// embedding `NAME_first_dart`.
void check_generated_names(const ast::Program& program, const resolve::Symbols& symbols,
                           diag::Diagnostics& diags);

}  // namespace rift::check
