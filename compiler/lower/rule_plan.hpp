// Lowering: a checked rule (or interaction pattern) becomes a plan the
// emitter can write out as straight-line code — how each left node is
// reached from a hook, which links must be verified, which darts are deleted
// and created, and which links the right pattern sets.
#pragma once

#include <vector>

#include "lower/checked.hpp"

namespace rift::lower {

/// left[to][r] = alpha_dim(left[from][r]).
struct Follow {
  int from = 0;
  int to = 0;
  int dim = 0;
};

/// alpha_dim(node a's dart) must be node b's dart in the same row (a == b: free).
struct ArcCheck {
  int a = 0;
  int b = 0;
  int dim = 0;
};

/// Node's darts linked along `dim` as the hook's darts are along label position `pos`.
struct LabelLink {
  int node = 0;
  int pos = 0;
  int dim = 0;
};

struct MatchPlan {
  std::vector<int> hooks;  // left node indices, in hook order
  int label_length = 0;    // entries of every label of the rule
  /// Hook j's label at [j * label_length, (j + 1) * label_length): the links
  /// that walk its instantiation orbit, position by position.
  std::vector<int> hook_dims;
  std::vector<Follow> follows;
  std::vector<ArcCheck> arc_checks;
  std::vector<LabelLink> label_checks;
};

struct RewritePlan {
  std::vector<int> deleted;          // left node indices
  std::vector<int> right_from_left;  // per right node: its left node, or -1 when created
  std::vector<ArcCheck> unlinks;  // (preserved right node, dim) cleared before relinking; b unused
  std::vector<ArcCheck> arcs;     // explicit right arcs (loops included: they stay free)
  std::vector<LabelLink> label_links;
  /// The dimensions whose links the rewrite changes, as a mask: those of an
  /// unlink whose relinking gives a dart another partner than it had. Links
  /// the right side gives back as the left side had them (the same label
  /// position, the same explicit arc) do not count.
  unsigned relinked_dims = 0;
  /// Whether the rewrite creates or deletes darts.
  bool darts_come_or_go = false;
};

MatchPlan plan_match(const check::RuleGraph& g);
RewritePlan plan_rewrite(const check::RuleGraph& g);

}  // namespace rift::lower
