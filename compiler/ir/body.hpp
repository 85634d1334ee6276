// The body of a declaration in the IR: its lets and whens in source order
// over one expression Graph, and what the body produces (an interaction's
// forces and energy). Lowered by lower/interaction_plan.cpp; rendered by
// emit/; transformed by passes that need the expressions (Jacobians).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/expr.hpp"

namespace rift::ir {

struct Let {
  std::string name;
  ExprId value = kNoExpr;
  diag::Location loc;
};

/// A let or a when, in the order the file writes them: a when that fails
/// stops the body before the lets after it are evaluated.
struct Stmt {
  enum class Kind { Let, When };
  Kind kind = Kind::Let;
  int let = -1;           // Let: index into Body::lets
  ExprId cond = kNoExpr;  // When: a bool
  diag::Location loc;
};

/// `force node.embedding = value`: added to the force of the vertex at
/// `vertex_slot` and stored, when asked, in `embedding` at `store_slot`.
struct Force {
  int node = 0;  // index into Body::nodes
  std::string embedding;
  int vertex_slot = -1;
  int store_slot = -1;
  ExprId value = kNoExpr;  // a vec3
  diag::Location loc;
};

/// `store node.embedding = value`: written at store_slot on the evaluation
/// whose forces are stored (its type is the embedding's).
struct Store {
  int node = 0;  // index into Body::nodes
  std::string embedding;
  /// `store node.embedding += value`: added at store_slot (a vertex slot
  /// the forces' scatter orders) after the pass zeroed it, not written.
  bool accumulate = false;
  int store_slot = -1;
  ExprId value = kNoExpr;
  diag::Location loc;
};

/// `jacobian a.f by b.position = value`: the block ∂f/∂x_b (∂f/∂v_b for a
/// velocity) of every force statement storing a.f, given by the rule rather
/// than derived (lower/derivative.hpp).
struct JacobianBlock {
  int node = 0;  // the force's node, index into Body::nodes
  std::string embedding;
  int by_node = 0;   // b, index into Body::nodes
  int by_slot = -1;  // the vertex slot of node b (the slot its `b.position` reads)
  bool velocity = false;
  ExprId value = kNoExpr;  // a mat3
  diag::Location loc;
};

/// What lets a renderer compute each shared value once (lower/share.hpp),
/// one entry per node of the graph; empty until the body is shared. (How
/// often a node is used depends on what one function renders: ir::count_uses.)
struct Sharing {
  /// Bit d is set when the node reads the dart variable of the fold at
  /// nesting depth d (1 = outermost): the node has one value per iteration
  /// of that fold, and none outside it. 0: the same value in the whole body.
  std::vector<std::uint32_t> fold_vars;
  /// The node may be evaluated before the place where it is written (ahead of
  /// an `if` that would skip it): false where that could be undefined
  /// behaviour in C++ (an integer division, an index computed at run time).
  std::vector<bool> speculable;
};

/// Values of a criterion's collection that depend only on the orbit `orbit`
/// of the dart of fold variable `var` (lower/orbit_memo.hpp): each is
/// computed once per collection and orbit, and read back by every cell whose
/// fold visits that orbit again (rift::generated::OrbitMemo).
struct OrbitMemo {
  int var = -1;                // index into Body::nodes: the fold variable whose dart keys the memo
  std::vector<int> orbit;      // the orbit of that dart the values depend on
  std::vector<ExprId> values;  // the memoised nodes, at most 64
};

struct Body {
  Graph graph;
  /// Names of the darts places refer to: the pattern nodes (in pattern
  /// order), then one per fold variable.
  std::vector<std::string> nodes;
  std::vector<Let> lets;
  std::vector<Stmt> stmts;    // lets and whens, in source order
  std::vector<Force> forces;  // in source order
  std::vector<Store> stores;  // in source order
  std::vector<JacobianBlock> jacobians;
  ExprId energy = kNoExpr;  // a real, or kNoExpr when the interaction has none
  Sharing sharing;          // filled by lower::share_common_subexpressions
};

}  // namespace rift::ir
