// Interactions become force kernels, criteria become evaluators that apply
// their rule where the measure passes its threshold, and initialisers become
// one sweep over the cells of their embedding's orbit.
#include "emit/emit_context.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

std::string int_list(const std::vector<int>& v) {
  std::string out;
  for (std::size_t k = 0; k < v.size(); ++k)
    out += (k ? ", " : "") + std::to_string(v[k]);
  return out;
}

ExprContext dart_context() {
  ExprContext ctx;
  ctx.dart = [](const std::string& node) { return dart_name(node); };
  return ctx;
}

}  // namespace

void emit_interaction(Writer& w, const check::CheckedInteraction& ci, const PackModel& model) {
  const ast::Interaction& inter = *ci.interaction;
  const check::RuleGraph& g = ci.graph;
  const lower::MatchPlan match = lower::plan_match(g);
  const std::string user = "interaction '" + inter.name.text + "'";
  const ExprContext ctx = dart_context();
  std::set<std::string> used;
  std::set<std::string> forces;
  for (const auto& l : inter.lets)
    embeddings_read(*l.value, used);
  for (const auto& e : inter.whens)
    embeddings_read(*e, used);
  for (const auto& f : inter.forces) {
    embeddings_read(*f.value, used);
    forces.insert(f.embedding.text);
  }
  if (inter.energy) embeddings_read(*inter.energy, used);
  used.insert(forces.begin(), forces.end());

  w.line("// " + user + ": support " + orbit_code(inter.support.dims));
  w.open("InteractionResult interaction_" + inter.name.text +
         "(rift::GMap& g, const Params& params) {");
  w.line("(void)params;");
  w.line("InteractionResult result;");
  fetch_embeddings(w, used, *model.symbols, user);
  // A support whose pattern no longer matches contributes nothing (§4.1): start from zero.
  for (const std::string& f : forces) {
    w.line("std::fill(" + embedding_var(f) + ".values().begin(), " + embedding_var(f) +
           ".values().end(), zero<rift::Vec3>());");
  }
  w.line("Scratch& s = scratch();");
  if (match.hook_dims.empty()) {
    w.line("const int* const hook_dims = nullptr;");
  } else {
    w.line("static constexpr int hook_dims[] = {" + int_list(match.hook_dims) + "};");
  }
  w.line("[[maybe_unused]] const std::size_t label = " + std::to_string(match.hook_dims.size()) +
         ";");
  w.open("g.for_each_cell(" + orbit_code(inter.support.dims) + ", [&](rift::Dart support) {");
  w.line("std::size_t rows = 1;");
  w.line("if (!build_rows(g, &support, 1, hook_dims, label, s, rows)) return;");
  emit_match(w, g, match, "return;");
  w.line("++result.matched;");
  w.open("for (std::size_t r = 0; r < rows; ++r) {");
  for (std::size_t v = 0; v < g.left.nodes.size(); ++v) {
    w.line("[[maybe_unused]] const rift::Dart " + dart_name(g.left.nodes[v].name()) + " = left_" +
           std::to_string(v) + "[r];");
  }
  write_lets(w, inter.lets, ctx);
  for (const auto& cond : inter.whens)
    write_sourced(w, cond->loc, "if (!(" + emit_expr(*cond, ctx) + ")) continue;");
  for (const ast::Assign& f : inter.forces) {
    write_sourced(w, f.value->loc,
                  embedding_var(f.embedding.text) + "[" + dart_name(f.node.text) +
                      "] = " + emit_expr(*f.value, ctx) + ";");
  }
  if (inter.energy) {
    write_sourced(w, inter.energy->loc,
                  "result.energy += " +
                      convert(emit_expr(*inter.energy, ctx), inter.energy->type, ast::Type::Real) +
                      ";");
  }
  w.close();
  w.close("});");
  w.line("return result;");
  w.close();
  w.line();
}

void emit_criterion(Writer& w, const ast::Criterion& crit, const PackModel& model) {
  const std::string user = "criterion '" + crit.name.text + "'";
  const ExprContext ctx = dart_context();
  const ast::Rule* rule = model.symbols->rule(crit.rule.text);
  std::set<std::string> used;
  for (const auto& l : crit.lets)
    embeddings_read(*l.value, used);
  embeddings_read(*crit.measure, used);
  for (const auto& a : crit.apply_args)
    embeddings_read(*a.value, used);
  const ast::Expr& lhs = *crit.measure->args[0];
  const ast::Expr& rhs = *crit.measure->args[1];
  const std::string args_type = rule->name.text + "_args";

  w.line("// " + user + " on " + orbit_code(crit.orbit.dims));
  w.open("CriterionResult criterion_" + crit.name.text + "(rift::GMap& g, const Params& params) {");
  w.line("CriterionResult result;");
  fetch_embeddings(w, used, *model.symbols, user);
  w.line("std::vector<std::pair<rift::Dart, " + args_type + ">> hits;");
  w.open("g.for_each_cell(" + orbit_code(crit.orbit.dims) + ", [&](rift::Dart " +
         dart_name(crit.dart.text) + ") {");
  write_lets(w, crit.lets, ctx);
  write_sourced(w, lhs.loc,
                "const rift::Real measure = " +
                    convert(emit_expr(lhs, ctx), lhs.type, ast::Type::Real) + ";");
  w.line("result.max_measure = std::max(result.max_measure, measure);");
  write_sourced(w, rhs.loc,
                "if (!(measure " + crit.measure->op + " " + emit_expr(rhs, ctx) + ")) return;");
  w.line(args_type + " args;");
  for (const ast::ApplyArg& a : crit.apply_args) {
    ast::Type want = ast::Type::Error;
    for (const auto& p : rule->params) {
      if (p.name.text == a.name.text) want = p.type;
    }
    write_sourced(w, a.value->loc,
                  "args." + member_name(a.name.text) + " = " +
                      convert(emit_expr(*a.value, ctx), a.value->type, want) + ";");
  }
  w.line("hits.emplace_back(" + dart_name(crit.dart.text) + ", args);");
  w.close("});");
  w.line("result.triggered = hits.size();");
  w.open("for (const auto& [dart, args] : hits) {");
  w.line("if (!g.is_alive(dart)) continue;");
  std::string hooks;
  for (std::size_t k = 0; k < crit.apply_hooks.size(); ++k)
    hooks += k ? ", dart" : "dart";
  w.line("const rift::Dart hooks[] = {" + hooks + "};");
  w.line("if (" + rule_function(rule->name.text) + "(g, hooks, args, params)) ++result.applied;");
  w.close();
  w.line("return result;");
  w.close();
  w.line();
}

void emit_initialisers(Writer& w, const PackModel& model) {
  w.open("void run_initialisers(rift::GMap& g, const Params& params) {");
  w.line("(void)g;");
  w.line("(void)params;");
  const ExprContext ctx = dart_context();
  for (const ast::File& file : model.program->files) {
    for (const ast::Init& init : file.inits) {
      const ast::Embedding* target = model.symbols->embedding(init.embedding.text);
      std::set<std::string> used;
      embeddings_read(*init.value, used);
      used.insert(init.embedding.text);
      w.open("{  // init " + init.embedding.text);
      fetch_embeddings(w, used, *model.symbols, "init " + init.embedding.text);
      w.open("g.for_each_cell(" + orbit_code(target->orbit.dims) + ", [&](rift::Dart " +
             dart_name(init.dart.text) + ") {");
      write_sourced(w, init.value->loc,
                    embedding_var(init.embedding.text) + "[" + dart_name(init.dart.text) + "] = " +
                        convert(emit_expr(*init.value, ctx), init.value->type, target->type) + ";");
      w.close("});");
      w.close();
    }
  }
  w.close();
  w.line();
}

}  // namespace rift::emit
