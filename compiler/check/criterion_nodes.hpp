// What a criterion's pattern nodes (`node b = a@2;`) may say beyond their
// names (resolve/ binds those): every link of a path is within the pack's
// dimension, and no node is always the same dart as another. A path whose
// links cancel (`a@0@0`, `a@0@2@0@2`: alpha_i is an involution and alpha_i,
// alpha_j commute when i + 2 <= j) reaches that dart on every map, so an
// injective match would never exist: riftc reports it rather than emitting a
// criterion that never holds.
#pragma once

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"

namespace rift::check {

void check_criterion_nodes(const ast::Program& program, diag::Diagnostics& diags);

}  // namespace rift::check
