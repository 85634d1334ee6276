// A script becomes one function with the signature of a rule function, so that
// criteria and other scripts call it like a rule. Its statements run in order
// on the current map: a `for each` first lists one dart per sub-orbit (on the
// map as it is when the statement starts), then, per dart still alive, checks
// its `where` and sets the embedding or applies the rule. Every application is
// a generated rule function, which matches again and keeps every check.
#include "emit/emit_context.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

std::set<std::string> script_embeddings(const ast::Script& script) {
  std::set<std::string> used;
  for (const ast::ScriptStmt& st : script.stmts) {
    if (st.kind == ast::ScriptStmt::Kind::Let) {
      embeddings_read(*script.lets[st.let].value, used);
      continue;
    }
    if (st.where) embeddings_read(*st.where, used);
    if (st.kind == ast::ScriptStmt::Kind::Set) {
      used.insert(st.set.embedding.text);
      embeddings_read(*st.set.value, used);
    }
    for (const auto& a : st.args)
      embeddings_read(*a.value, used);
  }
  return used;
}

const ast::Param* param_named(const std::vector<ast::Param>& params, const std::string& name) {
  for (const ast::Param& p : params) {
    if (p.name.text == name) return &p;
  }
  return nullptr;
}

/// Opens the loop of a statement: once (a do-while(false), so that a failed
/// `where` can `continue`), or once per listed sub-orbit dart.
void open_each(Writer& w, const ast::ScriptStmt& st, const ExprContext& ctx) {
  if (!st.each.present) {
    w.open("do {");
  } else {
    w.open("{");
    w.line("std::vector<rift::Dart> each;");
    w.line("g.for_each_sub_orbit(" + emit_dart(*st.each.dart, ctx) + ", " +
           orbit_code(st.each.outer.dims) + ", " + orbit_code(st.each.sub.dims) +
           ", [&](rift::Dart x) { each.push_back(x); });");
    w.open("for (const rift::Dart " + dart_name(st.each.var.text) + " : each) {");
    w.line("if (!g.is_alive(" + dart_name(st.each.var.text) + ")) continue;");
  }
  if (st.where) {
    write_sourced(w, st.where->loc, "if (!(" + emit_expr(*st.where, ctx) + ")) continue;");
  }
}

void close_each(Writer& w, const ast::ScriptStmt& st) {
  if (!st.each.present) {
    w.close("} while (false);");
    return;
  }
  w.close();
  w.close();
}

}  // namespace

void emit_script(Writer& w, const ast::Script& script, const PackModel& model) {
  const std::string user = "script '" + script.name.text + "'";
  ExprContext ctx;
  ctx.dart = [](const std::string& node) { return dart_name(node); };
  ctx.symbols = model.symbols;
  ctx.types = model.types;
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
  fetch_embeddings(w, script_embeddings(script), *model.symbols, user);
  w.line("bool applied = false;");
  for (const ast::ScriptStmt& st : script.stmts) {
    switch (st.kind) {
      case ast::ScriptStmt::Kind::Let: {
        const ast::Let& let = script.lets[st.let];
        write_sourced(w, let.value->loc,
                      "const " + cpp_type(ctx.types->of(*let.value)) + " " +
                          let_name(let.name.text) + " = " + emit_expr(*let.value, ctx) + ";");
        break;
      }
      case ast::ScriptStmt::Kind::Set: {
        open_each(w, st, ctx);
        const ast::Assign& a = st.set;
        write_sourced(w, a.value->loc,
                      embedding_var(a.embedding.text) + "[" + dart_name(a.node.text) + "] = " +
                          convert(emit_expr(*a.value, ctx), ctx.types->of(*a.value),
                                  model.symbols->target(a)->type) +
                          ";");
        // A value written in place is announced like a rewrite: interactions
        // that group identical matches by the values they read
        // (rift/sim/match_groups.hpp) re-key the matches around it.
        w.line("if (touched) touched->push_back(" + dart_name(a.node.text) + ");");
        close_each(w, st);
        break;
      }
      case ast::ScriptStmt::Kind::Apply: {
        open_each(w, st, ctx);
        const std::vector<ast::Param>* params = model.symbols->callee_params(st.rule.text);
        w.line(st.rule.text + "_args call;");
        for (const ast::ApplyArg& a : st.args) {
          const ast::Param* p = param_named(*params, a.name.text);
          write_sourced(w, a.value->loc,
                        "call." + member_name(a.name.text) + " = " +
                            convert(emit_expr(*a.value, ctx), ctx.types->of(*a.value), p->type) +
                            ";");
        }
        std::string hooks;
        for (std::size_t k = 0; k < st.hooks.size(); ++k)
          hooks += (k ? ", " : "") + emit_dart(*st.hooks[k], ctx);
        w.line("const rift::Dart at[] = {" + hooks + "};");
        w.line("if (" + rule_function(st.rule.text) +
               "(g, at, call, params, touched)) applied = true;");
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
