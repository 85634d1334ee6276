#include "lower/rule_plan.hpp"

#include <set>

#include "check/pattern_graph.hpp"

namespace rift::lower {

MatchPlan plan_match(const check::RuleGraph& g) {
  MatchPlan plan;
  plan.hooks = g.hooks;
  plan.label_length = g.hooks.empty() ? 0 : static_cast<int>(g.hook_labels.front().size());
  for (const std::vector<int>& label : g.hook_labels)
    plan.hook_dims.insert(plan.hook_dims.end(), label.begin(), label.end());
  const std::size_t n = g.left.nodes.size();
  std::vector<bool> reached(n, false);
  std::vector<bool> arc_used(g.left.arcs.size(), false);
  std::vector<int> queue = g.hooks;
  for (int h : g.hooks)
    reached[static_cast<std::size_t>(h)] = true;
  // Breadth-first from the hooks along explicit arcs: each arc either reaches
  // a new node (a Follow) or joins two reached ones (a check, done later).
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const int u = queue[k];
    for (std::size_t a = 0; a < g.left.arcs.size(); ++a) {
      const check::GraphArc& arc = g.left.arcs[a];
      if (arc_used[a] || (arc.a != u && arc.b != u)) continue;
      const int w = arc.a == u ? arc.b : arc.a;
      if (reached[static_cast<std::size_t>(w)]) continue;
      arc_used[a] = true;
      reached[static_cast<std::size_t>(w)] = true;
      plan.follows.push_back(Follow{u, w, arc.dim});
      queue.push_back(w);
    }
  }
  for (std::size_t a = 0; a < g.left.arcs.size(); ++a) {
    if (!arc_used[a])
      plan.arc_checks.push_back(ArcCheck{g.left.arcs[a].a, g.left.arcs[a].b, g.left.arcs[a].dim});
  }
  const std::set<int> hooks(g.hooks.begin(), g.hooks.end());
  for (std::size_t v = 0; v < n; ++v) {
    if (hooks.count(static_cast<int>(v))) continue;  // a hook's rows are its orbit by construction
    const std::vector<int>& label = g.left.nodes[v].label();
    for (std::size_t p = 0; p < label.size(); ++p) {
      if (label[p] >= 0)
        plan.label_checks.push_back(LabelLink{static_cast<int>(v), static_cast<int>(p), label[p]});
    }
  }
  return plan;
}

RewritePlan plan_rewrite(const check::RuleGraph& g) {
  RewritePlan plan;
  for (std::size_t v = 0; v < g.left.nodes.size(); ++v) {
    if (g.right.find(g.left.nodes[v].name()) < 0) plan.deleted.push_back(static_cast<int>(v));
  }
  for (std::size_t v = 0; v < g.right.nodes.size(); ++v) {
    const int l = g.left.find(g.right.nodes[v].name());
    plan.right_from_left.push_back(l);
    const std::vector<int>& label = g.right.nodes[v].label();
    std::set<int> dims;
    for (std::size_t p = 0; p < label.size(); ++p) {
      if (label[p] < 0) continue;
      dims.insert(label[p]);
      plan.label_links.push_back(LabelLink{static_cast<int>(v), static_cast<int>(p), label[p]});
    }
    for (const check::GraphArc& arc : g.right.arcs) {
      if (arc.a == static_cast<int>(v) || arc.b == static_cast<int>(v)) dims.insert(arc.dim);
    }
    if (l >= 0) {
      for (int d : dims)
        plan.unlinks.push_back(ArcCheck{static_cast<int>(v), static_cast<int>(v), d});
    }
  }
  for (const check::GraphArc& arc : g.right.arcs)
    plan.arcs.push_back(ArcCheck{arc.a, arc.b, arc.dim});
  return plan;
}

}  // namespace rift::lower
