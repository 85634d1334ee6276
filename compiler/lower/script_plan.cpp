#include "lower/script_plan.hpp"

#include "lower/expr_lower.hpp"

namespace rift::lower {

ScriptPlan lower_script(const ast::Script& script, const resolve::Symbols& symbols,
                        const check::ExprTypes& types) {
  ScriptPlan plan;
  plan.script = &script;
  ir::Body& b = plan.body;
  for (const ast::Ident& h : script.hooks)
    b.nodes.push_back(h.text);
  ExprLowering lowering(b.graph, b.nodes, nullptr, symbols, types);
  for (const ast::ScriptStmt& st : script.stmts) {
    ScriptStep step;
    if (st.kind == ast::ScriptStmt::Kind::Let) {
      const ast::Let& let = script.lets[st.let];
      step.kind = ScriptStep::Kind::Let;
      step.let = static_cast<int>(b.lets.size());
      b.lets.push_back({let.name.text, lowering.lower(*let.value), let.value->loc});
      lowering.add_let(&let, step.let);
      embeddings_read(b.graph, b.lets.back().value, plan.embeddings);
      plan.steps.push_back(std::move(step));
      continue;
    }
    if (st.each.present) {
      step.each = true;
      step.each_dart = lowering.place(*st.each.dart);
      step.each_outer = st.each.outer.dims;
      step.each_sub = st.each.sub.dims;
      b.nodes.push_back(st.each.var.text);
      step.each_var = static_cast<int>(b.nodes.size() - 1);
    }
    if (st.where) {
      step.where = lowering.lower(*st.where);
      step.where_loc = st.where->loc;
      embeddings_read(b.graph, step.where, plan.embeddings);
    }
    if (st.kind == ast::ScriptStmt::Kind::Set) {
      step.kind = ScriptStep::Kind::Set;
      const ast::Assign& a = st.set;
      // The newest node of that name: a `for each` variable shadows nothing else.
      for (std::size_t k = b.nodes.size(); k-- > 0;) {
        if (b.nodes[k] == a.node.text) {
          step.set.node = static_cast<int>(k);
          break;
        }
      }
      step.set.embedding = a.embedding.text;
      step.set.value = lowering.lower_as(*a.value, symbols.target(a)->type);
      step.set.loc = a.value->loc;
      add_name(plan.embeddings, a.embedding.text);
      embeddings_read(b.graph, step.set.value, plan.embeddings);
    } else {
      step.kind = ScriptStep::Kind::Apply;
      step.rule = st.rule.text;
      const std::vector<ast::Param>* params = symbols.callee_params(st.rule.text);
      for (const ast::ApplyArg& a : st.args) {
        ir::Type to = types.of(*a.value);
        for (const ast::Param& p : *params) {
          if (p.name.text == a.name.text) to = p.type;
        }
        step.args.push_back({a.name.text, lowering.lower_as(*a.value, to), a.value->loc});
        embeddings_read(b.graph, step.args.back().value, plan.embeddings);
      }
      for (const auto& h : st.hooks)
        step.hooks.push_back(lowering.place(*h));
    }
    plan.steps.push_back(std::move(step));
  }
  return plan;
}

}  // namespace rift::lower
