// Embedding consistency of rules: every right node gets a value for every
// embedding (inherited along its orbit, given by an expression, or the
// declared default), and orbits that a rule merges say what the merged value is.
#pragma once

#include <vector>

#include "check/topology.hpp"
#include "resolve/symbols.hpp"

namespace rift::check {

void check_embeddings(const std::vector<CheckedRule>& rules, const resolve::Symbols& symbols,
                      diag::Diagnostics& diags);

}  // namespace rift::check
