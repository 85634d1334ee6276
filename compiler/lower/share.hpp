// Common-subexpression elimination over a body's expression graph.
//
// Lowering writes each expression as a tree, so a value the rules spell out
// several times (a triangle's area inside a fold, the same inner fold in two
// places) is several nodes. This pass rebuilds the graph so that equal pure
// expressions are one node (hash-consing), and records for each node which fold
// variables it depends on and whether it may be computed ahead of where it
// is written (ir::Sharing). The renderer then computes a node used more than
// once by what it renders (ir::count_uses) into one named local
// at the innermost level where all its inputs exist: the statement level, or
// the body of the fold whose variable it reads. A node inside a fold that
// does not read the fold's variable is so computed once before the fold
// (loop-invariant code motion).
//
// Two folds are equal when they differ only in their variable's number:
// variables are renumbered by fold nesting depth and name, so the fifth
// `sum of outer(c.f, c.position) for each <1>(c) in <0,1>(f)` of a body is
// the first one. Everything in the IR is pure (reads of the map included),
// so sharing never changes a value; the order of the nodes, and so the names
// the renderer gives them, depend only on the body.
#pragma once

#include <vector>

#include "ir/body.hpp"

namespace rift::lower {

/// Rebuilds `body.graph` with equal expressions shared and fills
/// `body.sharing`. `roots` are every ExprId that refers into the graph
/// (lets, whens, forces and energy are found in the body itself; the caller
/// adds the others it holds, such as inits); they are updated in place, in
/// the order given.
void share_common_subexpressions(ir::Body& body, const std::vector<ir::ExprId*>& extra_roots);

}  // namespace rift::lower
