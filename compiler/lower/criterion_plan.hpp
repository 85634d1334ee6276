// A criterion lowered for emission: its lets, its measure and threshold and
// the arguments of the rule it applies, as one body in the IR, shared
// (lower/share.hpp) so that a value the criterion writes several times (a
// triangle's area, an element's stress inside a fold over the faces of a
// vertex) is computed once per place it can change, and a value of one
// element that several cells fold over is computed once per collection
// (lower/orbit_memo.hpp).
#pragma once

#include <cstddef>
#include <string>
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

/// One argument of a criterion's `apply`: computed by collect() where the
/// criterion holds and carried by the candidate to apply(), in the candidate's
/// payload (rift/core/candidate_payload.hpp).
struct PayloadField {
  std::string param;               ///< the parameter of the rule (or script) it fills
  ir::Type type = ir::Type::Real;  ///< the parameter's type; the value is converted to it
  std::size_t offset = 0;          ///< where it starts in the payload, in reals
  ir::ExprId value = ir::kNoExpr;
  diag::Location loc;  ///< of the value, for line directives
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
  /// Conditions without which the measure cannot pass, each tested as soon
  /// as its lets are computed, in this order (lower/measure_guards.hpp).
  std::vector<ir::ExprId> guards;
  /// The apply arguments in the order written, laid out one after the other
  /// (ast::payload_reals reals each); check/types.cpp proved they fit.
  std::vector<PayloadField> payload;
  std::size_t payload_reals = 0;  ///< the reals `payload` takes
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
