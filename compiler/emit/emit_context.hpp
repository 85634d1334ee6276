// Shared by the emitters of rules, interactions, criteria and initialisers:
// the checked program, the writer, and helpers to write expressions with
// #line directives pointing at the .rules file.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "ast/program.hpp"
#include "check/expr_types.hpp"
#include "check/topology.hpp"
#include "emit/expr_emit.hpp"
#include "emit/ir_render.hpp"
#include "emit/writer.hpp"
#include "lower/interaction_plan.hpp"
#include "lower/rule_plan.hpp"
#include "resolve/symbols.hpp"

namespace rift::emit {

struct PackModel {
  const ast::Program* program = nullptr;
  const resolve::Symbols* symbols = nullptr;
  const check::ExprTypes* types = nullptr;
  const std::vector<check::CheckedRule>* rules = nullptr;
  const std::vector<check::CheckedInteraction>* interactions = nullptr;
  const std::vector<lower::InteractionPlan>* interaction_plans =
      nullptr;                  // parallel to interactions
  std::string pack;             // the pack's name
  std::string pack_namespace;   // rift::packs::<pack>
  bool line_directives = true;  // #line into the .rules files
};

/// Name of the generated bool embedding on <> that tags the first dart of
/// each support orbit of a `tagged` interaction.
std::string tag_embedding(std::string_view interaction);

/// A constant expression (defaults), as C++.
std::string constant_expr(const ast::Expr& e, ast::Type to, const check::ExprTypes& types);

/// `struct NAME { T field = default; ... };` for scene-given parameters.
void declare_component_params(Writer& w, const std::string& name,
                              const std::vector<ast::Param>& params, const check::ExprTypes& types);
/// `NAME NAME_from(const rift::ComponentUse& use)`: reads (and checks) them from a scene.
void emit_component_params_reader(Writer& w, const std::string& name, const std::string& user,
                                  const std::vector<ast::Param>& params);
/// `{"stiffness", rift::ValueType::kReal, default, "description", positive, non_negative}, ...`
void write_param_specs(Writer& w, const std::vector<ast::Param>& params, bool from_scene,
                       const check::ExprTypes& types);

/// Names of the embeddings an expression reads.
void embeddings_read(const ast::Expr& e, std::set<std::string>& out);

/// `auto e_x = require_embedding<T>(g, "x", user);` for every name.
void fetch_embeddings(Writer& w, const std::set<std::string>& names,
                      const resolve::Symbols& symbols, const std::string& user);

/// `const T l_x = ...;` for each let, each with its #line.
void write_lets(Writer& w, const std::vector<ast::Let>& lets, const ExprContext& ctx);

/// The lets and whens of a body in source order; `on_fail` runs where a when is false.
void write_body(Writer& w, const std::vector<ast::Let>& lets,
                const std::vector<ast::ExprPtr>& whens, const std::vector<ast::BodyStmt>& body,
                const ExprContext& ctx, const std::string& on_fail);

/// One statement whose expression comes from `loc` in a .rules file.
void write_sourced(Writer& w, const diag::Location& loc, const std::string& statement);
/// `before + <id> + after` rendered by `r`, after the shared values it needs
/// first, all from `loc`; returns the C++ of `id`.
std::string write_rendered(Writer& w, BodyRenderer& r, const diag::Location& loc,
                           const std::string& before, ir::ExprId id, const std::string& after);

/// The matching code shared by rules and interactions: fills left_<v> for every
/// left node from the rows already built; `fail` is the statement run on a mismatch.
void emit_match(Writer& w, const check::RuleGraph& g, const lower::MatchPlan& match,
                const std::string& fail);

void emit_rule(Writer& w, const check::CheckedRule& rule, const PackModel& model);
void emit_script(Writer& w, const ast::Script& script, const PackModel& model);
void emit_initialisers(Writer& w, const PackModel& model);

/// Header declarations and source definitions of the generated classes.
void declare_kernel(Writer& w, const lower::InteractionPlan& inter, const PackModel& model);
void emit_kernel(Writer& w, const lower::InteractionPlan& inter, const PackModel& model);
void declare_criterion(Writer& w, const ast::Criterion& crit, const PackModel& model);
void emit_criterion(Writer& w, const ast::Criterion& crit, const PackModel& model);
/// A rule or script as a rift::Rule (arguments by position).
void declare_rule_class(Writer& w, const std::string& name, std::size_t hooks);
void emit_rule_class(Writer& w, const std::string& name, const std::vector<ast::Param>& params,
                     const check::ExprTypes& types);

}  // namespace rift::emit
