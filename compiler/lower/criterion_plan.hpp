// A criterion lowered for emission: its lets, its measure and threshold and
// the arguments of the rule it applies, as one body in the IR, shared
// (lower/share.hpp) so that a value the criterion writes several times (a
// triangle's area, an element's stress inside a fold over the faces of a
// vertex) is computed once per place it can change, and a value of one
// element that several cells fold over is computed once per collection
// (lower/orbit_memo.hpp).
#pragma once

#include <vector>

#include "ast/decl.hpp"
#include "ir/body.hpp"
#include "lower/checked.hpp"

namespace rift::lower {

/// A pattern node of a criterion (`node b = a@2@1;`): the dart reached from
/// an earlier node by crossing links. The criterion holds at a cell only where
/// every link crossed is sewn (not free) and the node is none of the earlier
/// nodes (an injective match); both are tested before anything else.
struct PatternNode {
  int from = 0;           // index into Body::nodes: the criterion's dart or an earlier node
  std::vector<int> hops;  // at least one
  /// Indices into Body::nodes of the earlier nodes this one must differ from;
  /// `from` is left out when the path is a single link, whose being sewn
  /// already makes the two darts distinct.
  std::vector<int> distinct_from;
  diag::Location loc;  // the path
};

struct CriterionPlan {
  const ast::Criterion* criterion = nullptr;
  /// nodes: the criterion's dart, then its pattern nodes (node k + 1 is
  /// pattern[k]), then fold variables; lets in source order (no whens,
  /// forces, energy).
  ir::Body body;
  std::vector<PatternNode> pattern;
  ir::ExprId measure = ir::kNoExpr;    // the left-hand side of the comparison, a real
  ir::ExprId threshold = ir::kNoExpr;  // the right-hand side, a real
  /// One per apply argument, parallel to Criterion::apply_args, of the type of
  /// the rule parameter it fills (`rule_params`, by name).
  std::vector<ir::ExprId> args;
  /// What collect() computes once per orbit and collection (lower/orbit_memo.hpp).
  std::vector<ir::OrbitMemo> memos;
  /// Whether collect() may evaluate several cells at once on several threads:
  /// it memoises nothing and walks only orbits of at most two links, which
  /// the map walks without marks (a mark is state of the whole map, and a fold
  /// over sub-orbits marks the darts it has seen).
  bool parallel_collect = false;
};

CriterionPlan plan_criterion(const ast::Criterion& crit, const std::vector<ast::Param>& rule_params,
                             const resolve::Symbols& symbols, const check::ExprTypes& types);

/// Marks in `used` (one entry per let) the lets `root` reads, directly or through other lets.
void lets_read(const ir::Body& body, ir::ExprId root, std::vector<bool>& used);

}  // namespace rift::lower
