// Pack-level initialisers (one sweep over the cells of their embedding's
// orbit) and the parameters a scene gives to interactions and criteria: their
// C++ struct, their reader from a rift::ComponentUse, their catalog entries.
#include "emit/emit_context.hpp"
#include "emit/ir_render.hpp"
#include "emit/names.hpp"

namespace rift::emit {

std::string constant_expr(const ast::Expr& e, const PackModel& model) {
  const lower::Constants& c = model.plan->constants;
  RenderContext ctx;
  ctx.dart = [](int) { return std::string("rift::kNoDart"); };
  return render(c.graph, c.of.at(&e), ctx);
}

void declare_component_params(Writer& w, const std::string& name,
                              const std::vector<ast::Param>& params, const PackModel& model) {
  w.line("/// Parameters given by the scene.");
  w.open("struct " + name + " {");
  for (const ast::Param& p : params) {
    const std::string value =
        p.default_value ? constant_expr(*p.default_value, model) : zero_of(p.type);
    w.line(cpp_type(p.type) + " " + member_name(p.name.text) + " = " + value + ";" +
           (p.description.empty() ? "" : "  ///< " + p.description));
  }
  w.close("};");
}

void emit_component_params_reader(Writer& w, const std::string& name, const std::string& user,
                                  const std::vector<ast::Param>& params) {
  w.open("[[maybe_unused]] " + name + " " + name +
         "_from([[maybe_unused]] const rift::ComponentUse& use) {");
  w.line(name + " p;");
  for (const ast::Param& p : params) {
    const std::string field = "p." + member_name(p.name.text);
    const std::string what = user + ": parameter '" + p.name.text + "'";
    w.open("if (auto it = use.params.find(" + quote(p.name.text) + "); it != use.params.end()) {");
    w.line(field + " = value_as<" + cpp_type(p.type) + ">(it->second.value, " + quote(what) + ");");
    if (!p.default_value) {
      w.middle("} else {");
      w.line("throw std::invalid_argument(" + quote(what + " is required") + ");");
    }
    w.close();
    if (p.bound == ast::Param::Bound::Positive) {
      w.line("if (!(" + field + " > 0)) throw std::invalid_argument(" +
             quote(what + " must be > 0") + ");");
    } else if (p.bound == ast::Param::Bound::NonNegative) {
      w.line("if (!(" + field + " >= 0)) throw std::invalid_argument(" +
             quote(what + " must be >= 0") + ");");
    }
  }
  w.line("return p;");
  w.close();
  w.line();
}

void write_param_specs(Writer& w, const std::vector<ast::Param>& params, bool from_scene,
                       const PackModel& model) {
  for (const ast::Param& p : params) {
    std::string def = "std::nullopt";
    if (from_scene && p.default_value) {
      def = "rift::Value(" + storage_type(p.type) + "(" + constant_expr(*p.default_value, model) +
            "))";
    }
    const bool positive = p.bound == ast::Param::Bound::Positive;
    const bool non_negative = p.bound == ast::Param::Bound::NonNegative;
    w.line(std::string("{") + quote(p.name.text) + ", " + value_type_enum(p.type) + ", " + def +
           ", " + quote(p.description) + ", " + (positive ? "true" : "false") + ", " +
           (non_negative ? "true" : "false") + "},");
  }
}

void emit_initialisers(Writer& w, const PackModel& model) {
  w.open("void run_initialisers(rift::GMap& g, const Params& params) {");
  w.line("(void)g;");
  w.line("(void)params;");
  // An imported pack's inits first, as its Pack would run them: what this
  // pack's inits and the imported rules read is then computed.
  for (const std::string& imported : model.plan->imports)
    w.line("rift::packs::" + imported + "::run_initialisers(g);");
  for (const lower::InitialiserPlan& init : model.plan->initialisers) {
    const lower::Write& a = init.write;
    const RenderContext ctx = dart_context(init.body);
    const std::string dart = ctx.dart(a.node);
    w.open("{  // init " + a.embedding);
    fetch_embeddings(w, init.embeddings, model, "init " + a.embedding);
    w.open("g.for_each_cell(" + orbit_code(init.orbit) + ", [&](rift::Dart " + dart + ") {");
    write_sourced(w, a.loc,
                  embedding_var(a.embedding) + "[" + dart +
                      "] = " + render(init.body.graph, a.value, ctx) + ";");
    w.close("});");
    w.close();
  }
  w.close();
  w.line();
}

}  // namespace rift::emit
