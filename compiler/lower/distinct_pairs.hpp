// The comparisons that make a pattern's match injective (no dart plays two
// nodes), fewer than one per pair of nodes.
//
// A matcher checks every explicit arc: after it succeeds, node v's dart's
// alpha_i is node w's dart for each arc v -i- w (w = v for a loop, v free
// along i). If two nodes p and q had one dart, and both have an i-arc, to p'
// and q', then p' and q' have one dart too: alpha_i of that dart. So a
// collision of the pair {p, q} forces a collision of {p', q'}, and back
// (alpha_i is an involution): the pairs linked this way, for any i, collide
// together or not at all, and one comparison per class of pairs decides
// the whole class. A hexahedron's 48-dart pattern, every node with its three
// arcs, needs 33 comparisons instead of 1128 (in the matcher of every
// volume, at set-up and after each tear).
#pragma once

#include <utility>
#include <vector>

#include "lower/rule_plan.hpp"

namespace rift::lower {

/// One pair {a, b} (a < b, node indices of the pattern) per class of pairs
/// that collide together, given the arcs the match checks (plan.follows and
/// plan.arc_checks), in increasing order. Comparing these pairs' darts is
/// comparing all of them.
std::vector<std::pair<int, int>> distinct_pairs(int nodes, const MatchPlan& plan);

}  // namespace rift::lower
