// Shared by the emitters of rules, interactions, criteria and initialisers:
// the lowered program (lower/pack_plan.hpp), the writer, and helpers to write
// the IR's statements with #line directives pointing at the .rules file.
// emit/ renders plans: it includes nothing from check/ or resolve/.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "ast/program.hpp"
#include "emit/ir_render.hpp"
#include "emit/writer.hpp"
#include "lower/pack_plan.hpp"

namespace rift::emit {

struct PackModel {
  const ast::Program* program = nullptr;
  const lower::PackPlan* plan = nullptr;  // every declaration, lowered
  std::string pack;                       // the pack's name
  std::string pack_namespace;             // rift::packs::<pack>
  bool line_directives = true;            // #line into the .rules files
};

/// The rule or script `callee` as an apply calls it: its arguments struct
/// (`split_vertex_args`) and its function (`apply_split_vertex`), qualified
/// with the namespace of the imported pack that generates it, if any
/// (`rift::packs::topology2d::apply_split_vertex`).
std::string callee_args(const PackModel& model, const std::string& callee);
std::string callee_function(const PackModel& model, const std::string& callee);
/// The pack parameters a call of `callee` passes: `pack_params` for this
/// pack's own rules and scripts; an imported pack's defaults (`{}`), the values
/// its own Pack uses, as a scene cannot set pack parameters.
std::string callee_params(const PackModel& model, const std::string& callee,
                          const std::string& pack_params);

/// Name of the generated bool embedding on <> that tags the first dart of
/// each support orbit of a `tagged` interaction.
std::string tag_embedding(std::string_view interaction);

/// A constant expression of a declaration (a default), as C++ of the type
/// of what it initialises (lower/initialiser_plan.hpp).
std::string constant_expr(const ast::Expr& e, const PackModel& model);

/// The C++ type an embedding holds (bool: rift::Bool).
std::string embedding_storage(const PackModel& model, const std::string& name);

/// `struct NAME { T field = default; ... };` for scene-given parameters.
void declare_component_params(Writer& w, const std::string& name,
                              const std::vector<ast::Param>& params, const PackModel& model);
/// `NAME NAME_from(const rift::ComponentUse& use)`: reads (and checks) them from a scene.
void emit_component_params_reader(Writer& w, const std::string& name, const std::string& user,
                                  const std::vector<ast::Param>& params);
/// `{"stiffness", rift::ValueType::kReal, default, "description", positive, non_negative}, ...`
void write_param_specs(Writer& w, const std::vector<ast::Param>& params, bool from_scene,
                       const PackModel& model);

/// `auto e_x = require_embedding<T>(g, "x", user);` for every name.
void fetch_embeddings(Writer& w, const std::vector<std::string>& names, const PackModel& model,
                      const std::string& user);

/// Reads darts by name: node k of `body` is `d_<its name>`.
RenderContext dart_context(const ir::Body& body);

/// The statements of `body` in source order that compute `roots`: the lets
/// they read (directly or through other lets), each `const T l_x = ...;`
/// with its #line, and, when `on_fail` is given, the whens, `on_fail`
/// running where one is false.
void write_statements(Writer& w, const ir::Body& body, const RenderContext& ctx,
                      const std::vector<ir::ExprId>& roots, const std::string* on_fail);

/// One statement whose expression comes from `loc` in a .rules file.
void write_sourced(Writer& w, const diag::Location& loc, const std::string& statement);
/// `before + <id> + after` rendered by `r`, after the shared values it needs
/// first, all from `loc`; returns the C++ of `id`.
std::string write_rendered(Writer& w, BodyRenderer& r, const diag::Location& loc,
                           const std::string& before, ir::ExprId id, const std::string& after);

/// The matching code shared by rules and interactions: fills left_<v> for every
/// left node from the rows already built; `fail` is the statement run on a mismatch.
void emit_match(Writer& w, const std::vector<std::string>& left, const lower::MatchPlan& match,
                const std::string& fail);

void emit_rule(Writer& w, const lower::RulePlan& rule, const PackModel& model);
void emit_script(Writer& w, const lower::ScriptPlan& script, const PackModel& model);
void emit_initialisers(Writer& w, const PackModel& model);

/// Header declarations and source definitions of the generated classes.
void declare_kernel(Writer& w, const lower::InteractionPlan& inter, const PackModel& model);
void emit_kernel(Writer& w, const lower::InteractionPlan& inter, const PackModel& model);
void declare_criterion(Writer& w, const lower::CriterionPlan& plan, const PackModel& model);
void emit_criterion(Writer& w, const lower::CriterionPlan& plan, const PackModel& model);
/// A rule or script as a rift::Rule (arguments by position).
void declare_rule_class(Writer& w, const std::string& name, std::size_t hooks);
void emit_rule_class(Writer& w, const std::string& name, const std::vector<ast::Param>& params,
                     const PackModel& model);

}  // namespace rift::emit
