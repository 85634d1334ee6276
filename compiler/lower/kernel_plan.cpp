#include "lower/kernel_plan.hpp"

#include <algorithm>

#include "check/kernels.hpp"
#include "check/topology.hpp"
#include "lower/distinct_pairs.hpp"

namespace rift::lower {

namespace {

std::vector<int> sorted(std::vector<int> dims) {
  std::sort(dims.begin(), dims.end());
  return dims;
}

class SlotCollector {
 public:
  SlotCollector(const check::RuleGraph& g, int dimension, const resolve::Symbols& symbols,
                KernelPlan& plan)
      : g_(g), dimension_(dimension), symbols_(symbols), plan_(plan) {}

  int add(int node, const std::vector<int>& hops, const std::vector<int>& orbit,
          const std::string& via) {
    const std::vector<int> o = sorted(orbit);
    const int found = plan_.find(node, hops, o);
    if (found >= 0) return found;
    SlotUse use;
    use.node = node;
    use.hops = hops;
    use.orbit = o;
    use.vertex = o == vertex_orbit(dimension_);
    use.via = use.vertex ? std::string(check::kPositionEmbedding) : via;
    plan_.slots.push_back(use);
    plan_.radius = std::max(
        plan_.radius, plan_.depth[static_cast<std::size_t>(node)] + static_cast<int>(hops.size()));
    return static_cast<int>(plan_.slots.size()) - 1;
  }

  void reads(const ast::Expr& e) {
    const ast::Embedding* embedding = symbols_.binding(e).embedding;
    if (e.kind == ast::Expr::Kind::Read && embedding) {
      add(g_.left.find(e.node), e.hops, embedding->orbit.dims, e.name);
    }
    for (const auto& a : e.args)
      reads(*a);
  }

 private:
  const check::RuleGraph& g_;
  int dimension_;
  const resolve::Symbols& symbols_;
  KernelPlan& plan_;
};

// The words of links from the support dart to every dart a match reads:
// each node's (the pattern reaches each node from an earlier one by one
// link, so a node's word extends an earlier node's), then each slot read
// through hops (its node's word, then the hops). Each word once.
//
// A word's first links that stay in the support orbit (links of its
// dimensions) are left out: walked back from a touched dart, the rest of
// the word ends in the support orbit of the match, which the re-match walks
// whole anyway. The quad's shear spring (support <0,1>, links 0 and 1 only)
// keeps the empty word alone, where its eight words walked 16 links from
// each touched dart, and the bend spring (support <2>) three of its six.
std::vector<std::vector<int>> reach_words(const KernelPlan& plan, const std::vector<int>& support) {
  if (plan.match.hooks.size() != 1) return {};
  std::vector<std::vector<int>> word(plan.nodes.size());
  std::vector<std::vector<int>> out = {{}};
  auto add = [&](std::vector<int> w) {
    const auto outside = std::find_if(w.begin(), w.end(), [&](int link) {
      return std::find(support.begin(), support.end(), link) == support.end();
    });
    w.erase(w.begin(), outside);
    if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(std::move(w));
  };
  for (const Follow& f : plan.match.follows) {
    std::vector<int> w = word[static_cast<std::size_t>(f.from)];
    w.push_back(f.dim);
    word[static_cast<std::size_t>(f.to)] = w;
    add(std::move(w));
  }
  for (const SlotUse& u : plan.slots) {
    std::vector<int> w = word[static_cast<std::size_t>(u.node)];
    w.insert(w.end(), u.hops.begin(), u.hops.end());
    add(std::move(w));
  }
  return out;
}

}  // namespace

std::vector<int> vertex_orbit(int dimension) {
  std::vector<int> out;
  for (int d = 1; d <= dimension; ++d)
    out.push_back(d);
  return out;
}

int KernelPlan::find(int node, const std::vector<int>& hops, const std::vector<int>& orbit) const {
  for (std::size_t k = 0; k < slots.size(); ++k) {
    if (slots[k].node == node && slots[k].hops == hops && slots[k].orbit == orbit) {
      return static_cast<int>(k);
    }
  }
  return -1;
}

KernelPlan plan_kernel(const check::CheckedInteraction& ci, const resolve::Symbols& symbols) {
  const ast::Interaction& inter = *ci.interaction;
  const check::RuleGraph& g = ci.graph;
  KernelPlan plan;
  for (const auto& n : g.left.nodes)
    plan.nodes.push_back(n.name());
  plan.match = plan_match(g);
  plan.distinct = distinct_pairs(static_cast<int>(plan.nodes.size()), plan.match);
  plan.depth.assign(g.left.nodes.size(), 0);
  plan.node_order = plan.match.hooks;
  for (const Follow& f : plan.match.follows) {
    plan.depth[static_cast<std::size_t>(f.to)] = plan.depth[static_cast<std::size_t>(f.from)] + 1;
    plan.node_order.push_back(f.to);
  }
  for (const ArcCheck& a : plan.match.arc_checks) {
    plan.radius = std::max(plan.radius, plan.depth[static_cast<std::size_t>(a.a)] + 1);
  }
  for (int d : plan.depth)
    plan.radius = std::max(plan.radius, d);

  SlotCollector collect(g, g.dimension, symbols, plan);
  for (const auto& l : inter.lets)
    collect.reads(*l.value);
  for (const auto& w : inter.whens)
    collect.reads(*w);
  for (const ast::Assign& f : inter.forces) {
    collect.reads(*f.value);
    const int node = g.left.find(f.node.text);
    ForceStore store;
    store.embedding = f.embedding.text;
    store.vertex_slot = collect.add(node, {}, vertex_orbit(g.dimension), "");
    store.store_slot = collect.add(node, {}, symbols.target(f)->orbit.dims, f.embedding.text);
    plan.forces.push_back(store);
  }
  for (const auto* list : {&inter.stores, &inter.accumulations}) {
    for (const ast::Assign& st : *list) {
      collect.reads(*st.value);
      plan.stores.push_back(collect.add(g.left.find(st.node.text), {},
                                        symbols.target(st)->orbit.dims, st.embedding.text));
    }
  }
  if (inter.energy) collect.reads(*inter.energy);
  // A block by b is of b's vertex, read or not; its value is a force-loop value.
  for (const ast::JacobianBlock& j : inter.jacobians) {
    collect.reads(*j.value);
    collect.add(g.left.find(j.by_node.text), {}, vertex_orbit(g.dimension), "");
  }
  plan.reach = reach_words(plan, inter.support.dims);
  return plan;
}

}  // namespace rift::lower
