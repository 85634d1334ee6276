// Type checking: computes the type of every expression and checks every place
// a value goes (lets, preconditions, embedding expressions, forces, energies,
// measures, defaults, parameters, initialisers).
#pragma once

#include "ast/program.hpp"
#include "check/expr_types.hpp"
#include "diag/diagnostics.hpp"
#include "resolve/symbols.hpp"

namespace rift::check {

void check_types(const ast::Program& program, const resolve::Symbols& symbols, ExprTypes& types,
                 diag::Diagnostics& diags);

/// Orbit labels used as orbit types (embeddings, supports, collections,
/// criteria): no `_`, no repeated dimension, every dimension in 0..n.
/// Returns false after reporting.
bool check_orbit_type(const ast::Label& label, int dimension, const char* what,
                      diag::Diagnostics& diags);

}  // namespace rift::check
