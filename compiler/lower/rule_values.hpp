// A rule lowered for emission: its topology (lower/rule_plan.hpp: the match
// and the change from L to R) and its expressions in the IR: its lets and
// whens in source order and the values of its right nodes, evaluated on the
// match, and its updates, evaluated on the right nodes after the rewrite.
// Every value is of the type of the embedding it is written to (int -> real
// made explicit).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ast/decl.hpp"
#include "ir/body.hpp"
#include "lower/checked.hpp"
#include "lower/rule_plan.hpp"

namespace rift::lower {

/// `node.embedding = value` written by a rule or a script.
struct Write {
  int node = 0;  // index into the body's nodes
  std::string embedding;
  ir::ExprId value = ir::kNoExpr;  // of the embedding's type
  diag::Location loc;
};

struct RuleValues {
  /// nodes: the left pattern nodes (then fold variables); lets and whens in
  /// source order in `stmts`.
  ir::Body match;
  std::vector<Write> assigns;  // parallel to Rule::right.assigns, nodes of `match`
  /// nodes: the right pattern nodes (then fold variables); no lets.
  ir::Body rewritten;
  std::vector<Write> updates;           // parallel to Rule::updates, nodes of `rewritten`
  std::vector<std::string> embeddings;  // every embedding read or written, sorted
};

struct RulePlan {
  const ast::Rule* rule = nullptr;
  int dimension = 2;                     // of the maps it applies to
  std::size_t hooks = 0;                 // how many darts a caller gives
  std::vector<std::string> left, right;  // the pattern nodes' names
  MatchPlan match;
  RewritePlan rewrite;
  std::vector<int> assign_nodes;  // per Rule::right.assigns, its right node
  RuleValues values;
};

RulePlan plan_rule(const check::CheckedRule& rule, const resolve::Symbols& symbols,
                   const check::ExprTypes& types);

/// Adds to `out` (sorted, unique) the embeddings read below `root`.
void embeddings_read(const ir::Graph& g, ir::ExprId root, std::vector<std::string>& out);
/// Adds `name` to `out` (sorted, unique).
void add_name(std::vector<std::string>& out, const std::string& name);

}  // namespace rift::lower
