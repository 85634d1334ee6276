#include "lower/rule_values.hpp"

#include <algorithm>

#include "check/expr_types.hpp"
#include "check/topology.hpp"
#include "lower/expr_lower.hpp"
#include "resolve/symbols.hpp"

namespace rift::lower {

namespace {

int index_of(const std::vector<std::string>& nodes, const std::string& name) {
  const auto it = std::find(nodes.begin(), nodes.end(), name);
  return it == nodes.end() ? -1 : static_cast<int>(it - nodes.begin());
}

Write lower_write(ExprLowering& lowering, const std::vector<std::string>& nodes,
                  const ast::Assign& a, const resolve::Symbols& symbols) {
  Write w;
  w.node = index_of(nodes, a.node.text);
  w.embedding = a.embedding.text;
  w.value = lowering.lower_as(*a.value, symbols.target(a)->type);
  w.loc = a.value->loc;
  return w;
}

}  // namespace

void add_name(std::vector<std::string>& out, const std::string& name) {
  const auto it = std::lower_bound(out.begin(), out.end(), name);
  if (it == out.end() || *it != name) out.insert(it, name);
}

void embeddings_read(const ir::Graph& g, ir::ExprId root, std::vector<std::string>& out) {
  if (root == ir::kNoExpr) return;
  ir::visit(g, root, [&](const ir::Node& n) {
    if (n.op == ir::Op::Read || n.op == ir::Op::Position || n.op == ir::Op::Velocity)
      add_name(out, n.embedding);
  });
}

namespace {

RuleValues lower_rule_values(const ast::Rule& rule, const check::RuleGraph& graph,
                             const resolve::Symbols& symbols, const check::ExprTypes& types) {
  RuleValues out;
  ir::Body& m = out.match;
  for (const auto& node : graph.left.nodes)
    m.nodes.push_back(node.name());
  ExprLowering match(m.graph, m.nodes, nullptr, symbols, types);
  for (const ast::BodyStmt& st : rule.body) {
    ir::Stmt s;
    if (st.kind == ast::BodyStmt::Kind::Let) {
      const ast::Let& let = rule.lets[st.index];
      s.kind = ir::Stmt::Kind::Let;
      s.let = static_cast<int>(m.lets.size());
      s.loc = let.value->loc;
      m.lets.push_back({let.name.text, match.lower(*let.value), let.value->loc});
      match.add_let(&let, s.let);
      embeddings_read(m.graph, m.lets.back().value, out.embeddings);
    } else {
      const ast::Expr& cond = *rule.whens[st.index];
      s.kind = ir::Stmt::Kind::When;
      s.cond = match.lower(cond);
      s.loc = cond.loc;
      embeddings_read(m.graph, s.cond, out.embeddings);
    }
    m.stmts.push_back(s);
  }
  for (const ast::Assign& a : rule.right.assigns) {
    out.assigns.push_back(lower_write(match, m.nodes, a, symbols));
    embeddings_read(m.graph, out.assigns.back().value, out.embeddings);
    add_name(out.embeddings, a.embedding.text);
  }
  ir::Body& r = out.rewritten;
  for (const auto& node : graph.right.nodes)
    r.nodes.push_back(node.name());
  ExprLowering after(r.graph, r.nodes, nullptr, symbols, types);
  for (const ast::Assign& u : rule.updates) {
    out.updates.push_back(lower_write(after, r.nodes, u, symbols));
    embeddings_read(r.graph, out.updates.back().value, out.embeddings);
    add_name(out.embeddings, u.embedding.text);
  }
  return out;
}

}  // namespace

RulePlan plan_rule(const check::CheckedRule& cr, const resolve::Symbols& symbols,
                   const check::ExprTypes& types) {
  const check::RuleGraph& g = cr.graph;
  RulePlan plan;
  plan.rule = cr.rule;
  plan.dimension = g.dimension;
  plan.hooks = g.hooks.size();
  for (const auto& node : g.left.nodes)
    plan.left.push_back(node.name());
  for (const auto& node : g.right.nodes)
    plan.right.push_back(node.name());
  plan.match = plan_match(g);
  plan.rewrite = plan_rewrite(g);
  for (const ast::Assign& a : cr.rule->right.assigns)
    plan.assign_nodes.push_back(g.right.find(a.node.text));
  plan.values = lower_rule_values(*cr.rule, g, symbols, types);
  return plan;
}

}  // namespace rift::lower
