// A rule's left and right patterns as graphs of node indices, built once and
// shared by the topological and embedding checks (and by lowering).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ast/decl.hpp"
#include "diag/diagnostics.hpp"

namespace rift::check {

struct GraphNode {
  const ast::NodeDecl* decl = nullptr;
  const std::string& name() const { return decl->name.text; }
  const std::vector<int>& label() const { return decl->label.dims; }
};

struct GraphArc {
  int a = 0;
  int b = 0;  // == a for a loop
  int dim = 0;
  const ast::Arc* decl = nullptr;
};

struct PatternSide {
  std::vector<GraphNode> nodes;
  std::vector<GraphArc> arcs;  // only arcs whose ends exist and whose dimension is in range
  int find(const std::string& name) const;
};

/// Where a node's darts go along one dimension: to `node` in the same row
/// (explicit arc or loop, pos = -1) or to itself in the row reached by the
/// hooks' link at label position `pos` (implicit arc). Rows are named by label
/// positions, not dimensions: hooks may have different labels, and their
/// orbits correspond position by position.
struct Step {
  int node = -1;
  int pos = -1;
  bool operator==(const Step& o) const { return node == o.node && pos == o.pos; }
};

struct RuleGraph {
  int dimension = 2;
  PatternSide left;
  PatternSide right;
  std::vector<int> hooks;  // left node indices, in hook order
  /// Per hook (in hook order), its label: the dimensions of its instantiation
  /// orbit, position by position. Hooks may have different labels (Jerboa:
  /// their orbits must be isomorphic after renaming, checked when matching).
  std::vector<std::vector<int>> hook_labels;
  int label_length = 0;
};

/// Builds one side, reporting duplicate names, arcs to unknown nodes, arc
/// dimensions and label entries out of range.
PatternSide build_side(const ast::Pattern& pattern, int dimension, diag::Diagnostics& diags);

/// Step of node v along dimension `dim` on one side, if it has an arc there.
std::optional<Step> step(const PatternSide& side, int v, int dim);

/// Connected components of a side through explicit arcs: component id per node.
std::vector<int> components(const PatternSide& side);

}  // namespace rift::check
