// Criteria become rift::Criterion classes: collect() evaluates the measure on
// every orbit of the criterion's type and proposes a TearCandidate where it
// holds; apply() matches the rule again at the candidate and rewrites,
// reporting the darts it touched. Rules also get a rift::Rule class, for
// simulators and scripts that apply them by name with run-time arguments.
#include "emit/emit_context.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

ExprContext criterion_context() {
  ExprContext ctx;
  ctx.dart = [](const std::string& node) { return dart_name(node); };
  ctx.args = "p_";
  ctx.params = "pack_";
  return ctx;
}

std::set<std::string> criterion_embeddings(const ast::Criterion& crit) {
  std::set<std::string> used;
  for (const auto& l : crit.lets)
    embeddings_read(*l.value, used);
  embeddings_read(*crit.measure, used);
  for (const auto& a : crit.apply_args)
    embeddings_read(*a.value, used);
  return used;
}

/// The rule parameter an apply argument fills, and whether the candidate
/// carries it (vec3 arguments named `normal` and `point`).
const ast::Param* rule_param(const std::vector<ast::Param>& params, const std::string& name) {
  for (const ast::Param& p : params) {
    if (p.name.text == name) return &p;
  }
  return nullptr;
}

bool carried(const ast::ApplyArg& a) {
  return a.value->type == ast::Type::Vec3 && (a.name.text == "normal" || a.name.text == "point");
}

}  // namespace

void declare_criterion(Writer& w, const ast::Criterion& crit, const PackModel& model) {
  const std::string cls = criterion_class(crit.name.text);
  const std::string params = component_params_struct(crit.name.text);
  declare_component_params(w, params, crit.params);
  w.line("/// Criterion '" + crit.name.text + "': applies rule '" + crit.rule.text +
         "' where its measure passes.");
  w.open("class " + cls + " final : public rift::Criterion {");
  w.middle(" public:");
  w.line("explicit " + cls + "(const " + params + "& p = {}, const Params& pack = {})");
  w.line("    : p_(p), pack_(pack) {}");
  w.line("const std::string& name() const override { return name_; }");
  w.line("const " + params + "& params() const { return p_; }");
  w.line("void initialise(rift::GMap& g) override;");
  w.line(
      "void collect(const rift::GMap& g, std::vector<rift::TearCandidate>& out) const override;");
  w.line("bool apply(rift::GMap& g, const rift::TearCandidate& candidate,");
  w.line("           std::vector<rift::Dart>& touched) override;");
  w.line();
  w.middle(" private:");
  w.line("std::string name_ = " + quote(crit.name.text) + ";");
  w.line(params + " p_;");
  // Not every body reads a pack-level parameter; clang warns of an unused field.
  w.line("[[maybe_unused]] Params pack_;");
  for (const std::string& name : criterion_embeddings(crit)) {
    w.line("rift::Embedding<" + storage_type(model.symbols->embedding(name)->type) + "> " +
           embedding_var(name) + ";");
  }
  w.close("};");
  w.line();
}

void emit_criterion(Writer& w, const ast::Criterion& crit, const PackModel& model) {
  const std::string cls = criterion_class(crit.name.text);
  const std::string user = "criterion '" + crit.name.text + "'";
  const ExprContext ctx = criterion_context();
  const std::vector<ast::Param>& rule_params = *model.symbols->callee_params(crit.rule.text);
  const ast::Expr& lhs = *crit.measure->args[0];
  const ast::Expr& rhs = *crit.measure->args[1];
  const std::string d = dart_name(crit.dart.text);
  w.line("// ---- criterion '" + crit.name.text + "' on " + orbit_code(crit.orbit.dims));
  w.line();
  w.open("void " + cls + "::initialise(rift::GMap& g) {");
  w.line(model.pack_namespace + "::declare_embeddings(g);");
  for (const std::string& name : criterion_embeddings(crit)) {
    w.line(embedding_var(name) + " = require_embedding<" +
           storage_type(model.symbols->embedding(name)->type) + ">(g, " + quote(name) + ", " +
           quote(user) + ");");
  }
  w.close();
  w.line();

  w.open("void " + cls +
         "::collect(const rift::GMap& g, std::vector<rift::TearCandidate>& out) const {");
  w.open("g.for_each_cell(" + orbit_code(crit.orbit.dims) + ", [&](rift::Dart " + d + ") {");
  // One relaxed load per cell: Ctrl-C is seen inside a long pass (a cell's
  // measure may traverse a large face).
  w.line("rift::throw_if_interrupted();");
  write_lets(w, crit.lets, ctx);
  write_sourced(w, lhs.loc,
                "const rift::Real measure = " +
                    convert(emit_expr(lhs, ctx), lhs.type, ast::Type::Real) + ";");
  write_sourced(w, rhs.loc,
                "const rift::Real threshold = " +
                    convert(emit_expr(rhs, ctx), rhs.type, ast::Type::Real) + ";");
  w.line("if (!(measure " + crit.measure->op + " threshold)) return;");
  w.line("rift::TearCandidate c;");
  w.line("c.at = " + d + ";");
  // Candidates are applied largest first: the margin by which the measure
  // passed, oriented by the comparison, puts the most critical first whether
  // the criterion is written with > or <.
  const bool above = crit.measure->op == ">" || crit.measure->op == ">=";
  w.line(std::string("c.measure = ") + (above ? "measure - threshold;" : "threshold - measure;"));
  for (const ast::ApplyArg& a : crit.apply_args) {
    if (!carried(a)) continue;
    write_sourced(w, a.value->loc, "c." + a.name.text + " = " + emit_expr(*a.value, ctx) + ";");
  }
  w.line("out.push_back(c);");
  w.close("});");
  w.close();
  w.line();

  // apply: the rule is matched again at the candidate's dart; `normal` and
  // `point` come from the candidate, other arguments are evaluated now.
  bool evaluates = false;
  for (const ast::ApplyArg& a : crit.apply_args)
    evaluates = evaluates || !carried(a);
  w.open("bool " + cls +
         "::apply(rift::GMap& g, const rift::TearCandidate& candidate, std::vector<rift::Dart>& "
         "touched) {");
  w.line("if (!g.is_alive(candidate.at)) return false;");
  w.line("[[maybe_unused]] const rift::Dart " + d + " = candidate.at;");
  if (evaluates) write_lets(w, crit.lets, ctx);
  w.line(crit.rule.text + "_args args;");
  for (const ast::ApplyArg& a : crit.apply_args) {
    const std::string field = "args." + member_name(a.name.text);
    if (carried(a)) {
      w.line(field + " = candidate." + a.name.text + ";");
      continue;
    }
    const ast::Param* p = rule_param(rule_params, a.name.text);
    write_sourced(w, a.value->loc,
                  field + " = " + convert(emit_expr(*a.value, ctx), a.value->type, p->type) + ";");
  }
  std::string hooks;
  for (std::size_t k = 0; k < crit.apply_hooks.size(); ++k)
    hooks += (k ? ", " : "") + dart_name(crit.apply_hooks[k].text);
  w.line("const rift::Dart hooks[] = {" + hooks + "};");
  w.line("return " + rule_function(crit.rule.text) + "(g, hooks, args, pack_, &touched);");
  w.close();
  w.line();
}

void declare_rule_class(Writer& w, const std::string& name, std::size_t hook_count) {
  const std::string cls = rule_class(name);
  w.line("/// Rule '" + name + "' as a rift::Rule: arguments by position.");
  w.open("class " + cls + " final : public rift::Rule {");
  w.middle(" public:");
  w.line("explicit " + cls + "(const Params& pack = {});");
  w.line("const std::string& name() const override { return name_; }");
  w.line("int hook_count() const override { return " + std::to_string(hook_count) + "; }");
  w.line("const std::vector<rift::ParamSpec>& params() const override { return specs_; }");
  w.line("bool apply(rift::GMap& g, std::span<const rift::Dart> hooks,");
  w.line(
      "           std::span<const rift::Value> args, std::vector<rift::Dart>& touched) override;");
  w.line();
  w.middle(" private:");
  w.line("std::string name_ = " + quote(name) + ";");
  // Not every body reads a pack-level parameter; clang warns of an unused field.
  w.line("[[maybe_unused]] Params pack_;");
  w.line("std::vector<rift::ParamSpec> specs_;");
  w.close("};");
  w.line();
}

void emit_rule_class(Writer& w, const std::string& name, const std::vector<ast::Param>& params) {
  const std::string cls = rule_class(name);
  w.open(cls + "::" + cls + "(const Params& pack) : pack_(pack) {");
  if (!params.empty()) {
    w.open("specs_ = {");
    write_param_specs(w, params, false);
    w.close("};");
  }
  w.close();
  w.line();
  w.open("bool " + cls +
         "::apply(rift::GMap& g, std::span<const rift::Dart> hooks, std::span<const rift::Value> "
         "args, std::vector<rift::Dart>& touched) {");
  w.open("if (args.size() != " + std::to_string(params.size()) + ") {");
  w.line(
      "throw std::invalid_argument(" +
      quote("rule '" + name + "' takes " + std::to_string(params.size()) + " argument(s), got ") +
      " + std::to_string(args.size()));");
  w.close();
  w.line(name + "_args a;");
  for (std::size_t k = 0; k < params.size(); ++k) {
    const ast::Param& p = params[k];
    w.line("a." + member_name(p.name.text) + " = value_as<" + cpp_type(p.type) + ">(args[" +
           std::to_string(k) + "], " +
           quote("argument '" + p.name.text + "' of rule '" + name + "'") + ");");
  }
  w.line("return " + rule_function(name) + "(g, hooks, a, pack_, &touched);");
  w.close();
  w.line();
}

}  // namespace rift::emit
