// The rows of a rule's match (JERBOA_RULES.md, "instantiation"): the darts of
// the hook orbit <H>(hook) in breadth-first order, one row per dart, and the
// same walk from every other hook. Generated matchers read a node's dart of a
// row from these arrays instead of walking the map again.
#pragma once

#include <cstddef>

#include "rift/generated/scratch.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift::generated {

/// Fills s.rows (hook j's dart of row r at rows[j * row_count + r]), s.nbr and
/// s.parent from the hooks. Hook j's label is hook_dims[j * label .. (j + 1) *
/// label): the first hook's walk numbers the rows, and every other hook
/// replays it with its own label, position by position. False when another
/// hook's walk does not meet an orbit isomorphic to the first's after that
/// renaming (Jerboa's condition for rules with several hooks). No hook: a
/// generator, one row and nothing matched.
bool build_rows(const GMap& g, const Dart* hooks, std::size_t hook_count, const int* hook_dims,
                std::size_t label, Scratch& s, std::size_t& row_count);

/// True when no dart of darts[0 .. count) appears twice: the match is
/// injective (no dart plays two nodes or two rows).
bool distinct_darts(const GMap& g, const Dart* darts, std::size_t count);

}  // namespace rift::generated
