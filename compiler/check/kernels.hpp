// What an interaction's force loop may do: it reads values through slots
// cached at match time, so it may not traverse the map (no collections), and
// positions and velocities come from the integrator's stage arrays, indexed
// by vertex slot, so they must live on the vertex orbit.
#pragma once

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"
#include "resolve/symbols.hpp"

namespace rift::check {

/// Names the integrator passes as stage arrays (ForceInput::x and ::v).
inline constexpr const char* kPositionEmbedding = "position";
inline constexpr const char* kVelocityEmbedding = "velocity";

void check_kernels(const ast::Program& program, const resolve::Symbols& symbols,
                   diag::Diagnostics& diags);

}  // namespace rift::check
