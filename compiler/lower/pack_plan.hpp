// Every declaration of a checked pack lowered: what emit/ renders. The driver
// runs parse -> resolve -> check -> lower (plan_pack) -> emit; emit/ decides
// nothing the checks decided (types, overloads, conversions, what names
// refer to): it reads them here.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ast/program.hpp"
#include "lower/criterion_plan.hpp"
#include "lower/initialiser_plan.hpp"
#include "lower/interaction_plan.hpp"
#include "lower/rule_values.hpp"
#include "lower/script_plan.hpp"

namespace rift::lower {

struct PackPlan {
  std::vector<RulePlan> rules;                // parallel to the checked rules
  std::vector<ScriptPlan> scripts;            // in source order
  std::vector<InitialiserPlan> initialisers;  // in source order
  std::vector<InteractionPlan> interactions;  // parallel to the checked interactions
  std::vector<CriterionPlan> criteria;        // in source order
  Constants constants;
  /// The embeddings the pack declares on a map, in source order: its own
  /// (not their restatements of the simulator's state, which resolve checked
  /// against rift's), and those of the state that it reads or writes. The
  /// other state columns are the runtime's to create: a pack that does not
  /// read vertex_force must not make the simulator fill it every step.
  std::vector<const ast::Embedding*> declared;
  /// The type of every embedding a name can refer to.
  std::map<std::string, ast::Type, std::less<>> embedding_types;
};

PackPlan plan_pack(const ast::Program& program, const std::vector<check::CheckedRule>& rules,
                   const std::vector<check::CheckedInteraction>& interactions,
                   const resolve::Symbols& symbols, const check::ExprTypes& types);

}  // namespace rift::lower
