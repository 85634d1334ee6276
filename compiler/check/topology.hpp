// Topological consistency (JERBOA_RULES.md): label housekeeping, hooks,
// incident arcs and the i-j-i-j cycles for i + 2 <= j. A rule that passes
// keeps every G-map it applies to valid.
#pragma once

#include <vector>

#include "ast/program.hpp"
#include "check/pattern_graph.hpp"
#include "diag/diagnostics.hpp"
#include "resolve/symbols.hpp"

namespace rift::check {

struct CheckedRule {
  const ast::Rule* rule = nullptr;
  RuleGraph graph;
  bool ok = false;  // no topological error: later passes may trust the graph
};

struct CheckedInteraction {
  const ast::Interaction* interaction = nullptr;
  RuleGraph graph;  // the pattern as the left side; right side empty
  bool ok = false;
};

std::vector<CheckedRule> check_rules(const ast::Program& program, diag::Diagnostics& diags);
std::vector<CheckedInteraction> check_interactions(const ast::Program& program,
                                                   const resolve::Symbols& symbols,
                                                   diag::Diagnostics& diags);
/// A criterion's `apply ... at` gives one dart per hook of the rule.
void check_applies(const ast::Program& program, const std::vector<CheckedRule>& rules,
                   diag::Diagnostics& diags);

}  // namespace rift::check
