#include "lower/pack_plan.hpp"

#include "check/expr_types.hpp"
#include "check/topology.hpp"
#include "resolve/symbols.hpp"

namespace rift::lower {

namespace {

/// Whether any expression, assignment or init of the pack reads or writes `e`.
bool is_used(const resolve::Symbols& s, const ast::Embedding& e) {
  for (const auto& [expr, binding] : s.bindings) {
    if (binding.embedding == &e) return true;
  }
  for (const auto& [assign, target] : s.assign_targets) {
    if (target == &e) return true;
  }
  for (const auto& [init, target] : s.init_targets) {
    if (target == &e) return true;
  }
  return false;
}

}  // namespace

PackPlan plan_pack(const ast::Program& program, const std::vector<check::CheckedRule>& rules,
                   const std::vector<check::CheckedInteraction>& interactions,
                   const resolve::Symbols& symbols, const check::ExprTypes& types) {
  PackPlan plan;
  for (const auto& [name, e] : symbols.embeddings)
    plan.embedding_types.emplace(name, e->type);
  for (const ast::File& file : program.files) {
    for (const ast::Embedding& e : file.embeddings) {
      if (symbols.embedding(e.name.text) != &e) continue;
      if (file.builtin && !is_used(symbols, e)) continue;
      plan.declared.push_back(&e);
    }
  }
  plan.rules.reserve(rules.size());
  for (const check::CheckedRule& cr : rules)
    plan.rules.push_back(plan_rule(cr, symbols, types));
  plan.interactions.reserve(interactions.size());
  for (const check::CheckedInteraction& ci : interactions)
    plan.interactions.push_back(plan_interaction(ci, symbols, types));
  for (const ast::File& file : program.files) {
    for (const ast::Script& s : file.scripts)
      plan.scripts.push_back(lower_script(s, symbols, types));
    for (const ast::Criterion& c : file.criteria)
      plan.criteria.push_back(
          plan_criterion(c, *symbols.callee_params(c.rule.text), symbols, types));
  }
  plan.initialisers = lower_initialisers(program, symbols, types);
  plan.constants = lower_constants(program, symbols, types);
  return plan;
}

}  // namespace rift::lower
