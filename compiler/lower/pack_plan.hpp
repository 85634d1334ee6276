// Every declaration of a checked pack lowered: what emit/ renders. The driver
// runs parse -> resolve -> check -> lower (plan_pack) -> emit; emit/ decides
// nothing the checks decided (types, overloads, conversions, what names
// refer to): it reads them here.
#pragma once

#include <map>
#include <set>
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
  // This pack's own declarations (not those of files an imported pack owns,
  // which that pack generates).
  std::vector<RulePlan> rules;                // in the order of the checked rules
  std::vector<ScriptPlan> scripts;            // in source order
  std::vector<InitialiserPlan> initialisers;  // in source order
  std::vector<InteractionPlan> interactions;  // in the order of the checked interactions
  std::vector<CriterionPlan> criteria;        // in source order
  Constants constants;
  /// The embeddings the pack declares on a map, in source order: its own
  /// (not their restatements of the simulator's state, which resolve checked
  /// against rift's), and those of the state that it reads or writes. The
  /// other state columns are the runtime's to create: a pack that does not
  /// read vertex_force must not make the simulator fill it every step.
  std::vector<const ast::Embedding*> declared;
  /// The packs this pack imports (ast::Program::imports): their generated
  /// headers are included, their inits run before this pack's, and
  /// registering this pack registers them.
  std::vector<std::string> imports;
  /// The pack of every rule and script an imported pack declares: an apply of
  /// one calls that pack's generated function, in its namespace.
  std::map<std::string, std::string, std::less<>> imported_callees;
  /// The scripts of imported packs, lowered only for what they read (a
  /// criterion applying one needs the forces its script reads stored).
  std::vector<ScriptPlan> imported_scripts;
  /// The type of every embedding a name can refer to.
  std::map<std::string, ast::Type, std::less<>> embedding_types;
  /// The embeddings of those on <>: the runtime keeps their values by dart
  /// (rift/embed/attachment.hpp), and generated readers read them so.
  std::set<std::string, std::less<>> per_dart;
};

PackPlan plan_pack(const ast::Program& program, const std::vector<check::CheckedRule>& rules,
                   const std::vector<check::CheckedInteraction>& interactions,
                   const resolve::Symbols& symbols, const check::ExprTypes& types);

}  // namespace rift::lower
