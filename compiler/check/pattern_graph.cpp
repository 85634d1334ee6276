#include "check/pattern_graph.hpp"

#include <map>
#include <numeric>

namespace rift::check {

int PatternSide::find(const std::string& name) const {
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (nodes[k].name() == name) return static_cast<int>(k);
  }
  return -1;
}

PatternSide build_side(const ast::Pattern& pattern, int dimension, diag::Diagnostics& diags) {
  PatternSide side;
  std::map<std::string, const ast::NodeDecl*> seen;
  for (const ast::NodeDecl& n : pattern.nodes) {
    auto [it, fresh] = seen.emplace(n.name.text, &n);
    if (!fresh) {
      diags.error(n.name.loc, "node '" + n.name.text + "' is declared twice in this pattern")
          .notes.push_back({it->second->name.loc, "first declared here"});
      continue;
    }
    for (int d : n.label.dims) {
      if (d < -1 || d > dimension) {
        diags.error(n.label.loc, "label entry " + std::to_string(d) + " of node '" + n.name.text +
                                     "' is out of range: entries are '_' or 0.." +
                                     std::to_string(dimension));
        break;
      }
    }
    side.nodes.push_back(GraphNode{&n});
  }
  for (const ast::Arc& arc : pattern.arcs) {
    const int a = side.find(arc.a.text);
    const int b = side.find(arc.b.text);
    bool ok = true;
    for (const ast::Ident* end : {&arc.a, &arc.b}) {
      if (side.find(end->text) < 0) {
        diags.error(end->loc,
                    "arc refers to '" + end->text + "', which is not a node of this pattern");
        ok = false;
        if (arc.a.text == arc.b.text) break;
      }
    }
    if (arc.dim < 0 || arc.dim > dimension) {
      diags.error(arc.dim_loc, "arc dimension " + std::to_string(arc.dim) + " is out of range 0.." +
                                   std::to_string(dimension));
      ok = false;
    }
    if (ok) side.arcs.push_back(GraphArc{a, b, arc.dim, &arc});
  }
  return side;
}

std::optional<Step> step(const PatternSide& side, int v, int dim) {
  for (const GraphArc& arc : side.arcs) {
    if (arc.dim != dim) continue;
    if (arc.a == v) return Step{arc.b, -1};
    if (arc.b == v) return Step{arc.a, -1};
  }
  const std::vector<int>& label = side.nodes[static_cast<std::size_t>(v)].label();
  for (std::size_t p = 0; p < label.size(); ++p) {
    if (label[p] == dim) return Step{v, static_cast<int>(p)};
  }
  return std::nullopt;
}

std::vector<int> components(const PatternSide& side) {
  std::vector<int> parent(side.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int x) {
    while (parent[static_cast<std::size_t>(x)] != x)
      x = parent[static_cast<std::size_t>(x)];
    return x;
  };
  for (const GraphArc& arc : side.arcs)
    parent[static_cast<std::size_t>(root(arc.a))] = root(arc.b);
  std::vector<int> comp(side.nodes.size());
  for (std::size_t k = 0; k < comp.size(); ++k)
    comp[k] = root(static_cast<int>(k));
  return comp;
}

}  // namespace rift::check
