// A script becomes one function with the signature of a rule function, so that
// criteria and other scripts call it like a rule. Its statements run in order
// on the current map: a `for each` first lists one dart per sub-orbit (on the
// map as it is when the statement starts, in a buffer the thread keeps, so
// that a warm rewrite allocates nothing), then, per dart still alive, checks
// its `where` and sets the embedding or applies the rule. Every application is
// a generated rule function, which matches again and keeps every check.
#include "emit/emit_context.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

/// Opens the loop of a statement: once (a do-while(false), so that a failed
/// `where` can `continue`), or once per listed sub-orbit dart.
void open_each(Writer& w, const lower::ScriptStep& st, const ir::Body& body,
               const RenderContext& ctx) {
  if (!st.each) {
    w.open("do {");
  } else {
    const std::string var = ctx.dart(st.each_var);
    w.open("{");
    w.line("rift::generated::DartList each;");
    w.line("g.for_each_sub_orbit(" + render_place(st.each_dart, ctx) + ", " +
           orbit_code(st.each_outer) + ", " + orbit_code(st.each_sub) +
           ", [&](rift::Dart x) { each.push_back(x); });");
    w.open("for (const rift::Dart " + var + " : each) {");
    w.line("if (!g.is_alive(" + var + ")) continue;");
  }
  if (st.where != ir::kNoExpr) {
    write_sourced(w, st.where_loc, "if (!(" + render(body.graph, st.where, ctx) + ")) continue;");
  }
}

void close_each(Writer& w, const lower::ScriptStep& st) {
  if (!st.each) {
    w.close("} while (false);");
    return;
  }
  w.close();
  w.close();
}

}  // namespace

void emit_script(Writer& w, const lower::ScriptPlan& plan, const PackModel& model) {
  const ast::Script& script = *plan.script;
  const ir::Body& body = plan.body;
  const std::string user = "script '" + script.name.text + "'";
  const RenderContext ctx = dart_context(body);
  w.line("// " + user + " (" + std::to_string(script.hooks.size()) + " hook(s))");
  w.open("bool " + rule_function(script.name.text) +
         "(rift::GMap& g, std::span<const rift::Dart> hooks, const " + script.name.text +
         "_args& args, const Params& params, std::vector<rift::Dart>* touched) {");
  w.line("(void)args;");
  w.line("(void)params;");
  w.line("if (g.dimension() != " + std::to_string(model.program->dimension) +
         ") throw std::invalid_argument(" +
         quote(user + " needs a G-map of dimension " + std::to_string(model.program->dimension)) +
         ");");
  w.line("if (hooks.size() != " + std::to_string(script.hooks.size()) + ") return false;");
  w.open("for (rift::Dart h : hooks) {");
  w.line("if (!g.is_alive(h)) return false;");
  w.close();
  for (std::size_t k = 0; k < script.hooks.size(); ++k) {
    w.line("[[maybe_unused]] const rift::Dart " + dart_name(script.hooks[k].text) + " = hooks[" +
           std::to_string(k) + "];");
  }
  fetch_embeddings(w, plan.embeddings, model, user);
  w.line("bool applied = false;");
  for (const lower::ScriptStep& st : plan.steps) {
    switch (st.kind) {
      case lower::ScriptStep::Kind::Let: {
        const ir::Let& let = body.lets[static_cast<std::size_t>(st.let)];
        write_sourced(w, let.loc,
                      "const " + cpp_type(body.graph[let.value].type) + " " + let_name(let.name) +
                          " = " + render(body.graph, let.value, ctx) + ";");
        break;
      }
      case lower::ScriptStep::Kind::Set: {
        open_each(w, st, body, ctx);
        const lower::Write& a = st.set;
        const std::string dart = ctx.dart(a.node);
        write_sourced(w, a.loc,
                      embedding_var(a.embedding) + "[" + dart +
                          "] = " + render(body.graph, a.value, ctx) + ";");
        // A value written in place is announced like a rewrite: interactions
        // that group identical matches by the values they read
        // (rift/sim/match_groups.hpp) re-key the matches around it.
        w.line("if (touched) touched->push_back(" + dart + ");");
        close_each(w, st);
        break;
      }
      case lower::ScriptStep::Kind::Apply: {
        open_each(w, st, body, ctx);
        w.line(callee_args(model, st.rule) + " call;");
        for (const lower::ScriptStep::Arg& a : st.args) {
          write_sourced(
              w, a.loc,
              "call." + member_name(a.param) + " = " + render(body.graph, a.value, ctx) + ";");
        }
        std::string hooks;
        for (std::size_t k = 0; k < st.hooks.size(); ++k)
          hooks += (k ? ", " : "") + render_place(st.hooks[k], ctx);
        w.line("const rift::Dart at[] = {" + hooks + "};");
        w.line("if (" + callee_function(model, st.rule) + "(g, at, call, " +
               callee_params(model, st.rule, "params") + ", touched)) applied = true;");
        close_each(w, st);
        break;
      }
    }
  }
  w.line("return applied;");
  w.close();
  w.line();
}

}  // namespace rift::emit
