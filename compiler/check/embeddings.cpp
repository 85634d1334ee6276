#include "check/embeddings.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace rift::check {

namespace {

/// The embedding's orbits seen on one side of a rule: node-level classes joined
/// by explicit arcs whose dimension is in the orbit, and for each class the
/// hook links along which its rows are joined by implicit arcs.
struct OrbitClasses {
  std::vector<int> cls;                    // class id per node
  std::map<int, std::set<int>> row_links;  // class id -> label positions of the row links
};

OrbitClasses classes(const PatternSide& side, const std::set<int>& orbit) {
  OrbitClasses out;
  out.cls.resize(side.nodes.size());
  std::iota(out.cls.begin(), out.cls.end(), 0);
  auto root = [&](int x) {
    while (out.cls[static_cast<std::size_t>(x)] != x)
      x = out.cls[static_cast<std::size_t>(x)];
    return x;
  };
  for (const GraphArc& arc : side.arcs) {
    if (orbit.count(arc.dim)) out.cls[static_cast<std::size_t>(root(arc.a))] = root(arc.b);
  }
  for (std::size_t v = 0; v < side.nodes.size(); ++v) {
    out.cls[v] = root(static_cast<int>(v));
    const std::vector<int>& label = side.nodes[v].label();
    std::set<int>& links = out.row_links[out.cls[v]];
    for (std::size_t p = 0; p < label.size(); ++p) {
      if (orbit.count(label[p])) links.insert(static_cast<int>(p));
    }
  }
  return out;
}

void check_rule_embedding(const CheckedRule& cr, const ast::Embedding& emb,
                          const resolve::Symbols& symbols, diag::Diagnostics& diags) {
  const RuleGraph& g = cr.graph;
  const std::set<int> orbit(emb.orbit.dims.begin(), emb.orbit.dims.end());
  const OrbitClasses left = classes(g.left, orbit);
  const OrbitClasses right = classes(g.right, orbit);
  const std::string& e = emb.name.text;

  // Expressions for this embedding, per right class.
  std::map<int, const ast::Assign*> given;
  for (const ast::Assign& a : cr.rule->right.assigns) {
    if (symbols.target(a) != &emb) continue;
    const int v = g.right.find(a.node.text);
    if (v < 0) continue;  // reported once, by check_assign_targets
    const int c = right.cls[static_cast<std::size_t>(v)];
    auto [it, fresh] = given.emplace(c, &a);
    if (!fresh) {
      diags.error(a.loc, "'" + e + "' is given twice for one " + e + "-orbit")
          .notes.push_back({it->second->loc, "first given here"});
    }
  }

  std::set<int> seen;
  for (std::size_t v = 0; v < g.right.nodes.size(); ++v) {
    const int c = right.cls[v];
    if (!seen.insert(c).second || given.count(c)) continue;
    std::vector<int> preserved;  // left indices of the class's preserved nodes
    const GraphNode* created = nullptr;
    for (std::size_t w = 0; w < g.right.nodes.size(); ++w) {
      if (right.cls[w] != c) continue;
      const int l = g.left.find(g.right.nodes[w].name());
      if (l >= 0) {
        preserved.push_back(l);
      } else if (!created) {
        created = &g.right.nodes[w];
      }
    }
    if (preserved.empty()) {
      if (emb.default_value) continue;
      diags
          .error(created->decl->name.loc,
                 "created node '" + created->name() + "' gets no value for '" + e + "': its " + e +
                     "-orbit holds no preserved node; give '" + created->name() + "." + e +
                     " = ...' in the right pattern or a default to the embedding")
          .notes.push_back({emb.name.loc, "'" + e + "' declared here"});
      continue;
    }
    if (emb.merge) continue;  // the declared policy says what a merged value is
    std::set<int> left_classes;
    for (int l : preserved)
      left_classes.insert(left.cls[static_cast<std::size_t>(l)]);
    const GraphNode& first = g.left.nodes[static_cast<std::size_t>(preserved.front())];
    const GraphNode* rnode = &g.right.nodes[static_cast<std::size_t>(g.right.find(first.name()))];
    if (left_classes.size() > 1) {
      const GraphNode* other = nullptr;
      for (int l : preserved) {
        if (left.cls[static_cast<std::size_t>(l)] !=
            left.cls[static_cast<std::size_t>(preserved.front())]) {
          other = &g.left.nodes[static_cast<std::size_t>(l)];
          break;
        }
      }
      diags
          .error(rnode->decl->name.loc,
                 "the rule merges the " + e + "-orbits of '" + first.name() + "' and '" +
                     other->name() + "' but says nothing of the merged value; give '" +
                     first.name() + "." + e + " = ...' or declare a merge policy")
          .notes.push_back({emb.name.loc, "'" + e + "' declared here"});
      continue;
    }
    const std::set<int>& before = left.row_links.at(*left_classes.begin());
    const std::set<int>& after = right.row_links.at(c);
    if (!std::includes(before.begin(), before.end(), after.begin(), after.end())) {
      diags
          .error(rnode->decl->name.loc,
                 "the relabelling of '" + first.name() + "' merges several of its " + e +
                     "-orbits into one but says nothing of the merged value; give '" +
                     first.name() + "." + e + " = ...' or declare a merge policy")
          .notes.push_back({emb.name.loc, "'" + e + "' declared here"});
    }
  }
}

/// Right-node expressions and updates name right nodes, each at most once.
void check_assign_targets(const CheckedRule& cr, diag::Diagnostics& diags) {
  std::map<std::pair<std::string, std::string>, const ast::Assign*> seen;
  for (const ast::Assign& a : cr.rule->right.assigns) {
    if (cr.graph.right.find(a.node.text) < 0) {
      diags.error(a.node.loc, "'" + a.node.text + "' is not a node of the right pattern");
      continue;
    }
    auto [it, fresh] = seen.emplace(std::make_pair(a.node.text, a.embedding.text), &a);
    if (!fresh) {
      diags.error(a.loc, "'" + a.node.text + "." + a.embedding.text + "' is given twice")
          .notes.push_back({it->second->loc, "first given here"});
    }
  }
}

}  // namespace

void check_embeddings(const std::vector<CheckedRule>& rules, const resolve::Symbols& symbols,
                      diag::Diagnostics& diags) {
  for (const CheckedRule& cr : rules) {
    check_assign_targets(cr, diags);
    if (!cr.ok) continue;
    for (const auto& [name, emb] : symbols.embeddings) {
      bool in_range = true;
      for (int d : emb->orbit.dims)
        in_range = in_range && d >= 0 && d <= cr.graph.dimension;
      if (in_range) check_rule_embedding(cr, *emb, symbols, diags);
    }
  }
}

}  // namespace rift::check
