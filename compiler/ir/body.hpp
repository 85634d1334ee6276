// The body of a declaration in the IR: its lets and whens in source order
// over one expression Graph, and what the body produces (an interaction's
// forces and energy). Lowered by lower/interaction_plan.cpp; rendered by
// emit/; transformed by passes that need the expressions (Jacobians).
#pragma once

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

struct Body {
  Graph graph;
  /// Names of the darts places refer to: the pattern nodes (in pattern
  /// order), then one per fold variable.
  std::vector<std::string> nodes;
  std::vector<Let> lets;
  std::vector<Stmt> stmts;    // lets and whens, in source order
  std::vector<Force> forces;  // in source order
  ExprId energy = kNoExpr;    // a real, or kNoExpr when the interaction has none
};

}  // namespace rift::ir
