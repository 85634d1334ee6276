#include "lower/rule_plan.hpp"

#include <algorithm>
#include <set>
#include <string>

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

namespace {

// The explicit arcs of node v along dim on one side, as the partners' names
// ("" for a loop: v is free along dim).
std::multiset<std::string> arc_partners(const check::PatternSide& side, int v, int dim) {
  std::multiset<std::string> out;
  for (const check::GraphArc& arc : side.arcs) {
    if (arc.dim != dim) continue;
    if (arc.a == v && arc.b == v) {
      out.insert("");
    } else if (arc.a == v) {
      out.insert(side.nodes[static_cast<std::size_t>(arc.b)].name());
    } else if (arc.b == v) {
      out.insert(side.nodes[static_cast<std::size_t>(arc.a)].name());
    }
  }
  return out;
}

// Whether right node v (kept from a left node) has along `dim` the links its
// left node had: the same label positions holding dim, and the same explicit
// arcs (partners by name). The rewrite unlinks and relinks such a link to the
// same partner, which changes no orbit.
bool same_links(const check::RuleGraph& g, const std::vector<int>& right_from_left, int v,
                int dim) {
  const int l = right_from_left[static_cast<std::size_t>(v)];
  if (l < 0) return false;
  const std::vector<int>& left_label = g.left.nodes[static_cast<std::size_t>(l)].label();
  const std::vector<int>& right_label = g.right.nodes[static_cast<std::size_t>(v)].label();
  if (left_label.size() != right_label.size()) return false;
  for (std::size_t p = 0; p < left_label.size(); ++p) {
    if ((left_label[p] == dim) != (right_label[p] == dim)) return false;
  }
  return arc_partners(g.left, l, dim) == arc_partners(g.right, v, dim);
}

}  // namespace

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
  plan.darts_come_or_go = !plan.deleted.empty() ||
                          std::find(plan.right_from_left.begin(), plan.right_from_left.end(), -1) !=
                              plan.right_from_left.end();
  for (const ArcCheck& u : plan.unlinks) {
    if (!same_links(g, plan.right_from_left, u.a, u.dim)) plan.relinked_dims |= 1u << u.dim;
  }
  return plan;
}

}  // namespace rift::lower
