// Orbit memos: values of a criterion's collection that depend only on one
// orbit of a fold's dart, computed once per collection and orbit.
//
// A criterion on vertices folding over each vertex's tetrahedra,
//
//   sum of (sum corner_mass over <0,1,2>(c)) * ... for each <0,1,2>(c) in <1,2,3>(v)
//
// evaluates `sum corner_mass over <0,1,2>(c)` for every (vertex, tetrahedron)
// pair: four times per tetrahedron, one 24-dart walk each. The value is a
// function of the orbit <0,1,2>(c) alone, so the generated collect() computes
// it on the first visit of the orbit and reads it back on the others
// (rift::generated::OrbitMemo, stamped with the collection's number: no value
// outlives the collection, so a tear never leaves a stale one).
//
// A node X (an aggregate `over` or a fold `of ... for each`) is memoised
// where it stands inside a fold F with dart variable c, and:
//  - X starts at c itself (no hops), over an orbit O that contains F's
//    sub-orbit: every dart F may pick for the same sub-orbit gives the same O(c);
//  - O is not inside the criterion's cell orbit (otherwise no other cell
//    reaches O(c), and there would be nothing to reuse);
//  - X reads nothing but the darts of O(c): no let, no pattern node, no
//    other fold's variable, and no hop; and a fold inside X reads at its own
//    variable only embeddings (and aggregates) on orbits that contain its
//    sub-orbit, so that its value does not depend on which dart of each
//    sub-orbit the walk picks. Parameters are read freely (constant during
//    a collection).
// So X's value is the same for every dart of O(c) up to the order in which
// its walk adds the terms: a sum may then differ in its last bits from an
// evaluation from another dart (min, max and count do not).
//
// Only a criterion's collect() uses the memos; apply() evaluates on a map
// that earlier rewrites of the same step have changed, and never memoises.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ir/body.hpp"

namespace rift::lower {

/// The orbit an embedding lives on (its dimensions).
using EmbeddingOrbit = std::function<std::vector<int>(const std::string& embedding)>;

/// Whether every dimension of orbit `inner` is one of orbit `outer`'s.
bool orbit_contains(const std::vector<int>& outer, const std::vector<int>& inner);

/// The memos of the nodes reachable from `roots` in `body` (already shared,
/// lower/share.hpp), for a criterion on cells of orbit `cell_orbit`; grouped by
/// (fold variable, orbit), in node order. Outermost nodes only: a memoised
/// node's operands are computed inside it.
std::vector<ir::OrbitMemo> plan_orbit_memos(const ir::Body& body,
                                            const std::vector<ir::ExprId>& roots,
                                            const std::vector<int>& cell_orbit,
                                            const EmbeddingOrbit& embedding_orbit);

}  // namespace rift::lower
