#include "lower/criterion_plan.hpp"

#include <algorithm>

#include "lower/expr_lower.hpp"
#include "lower/measure_guards.hpp"
#include "lower/orbit_memo.hpp"
#include "lower/share.hpp"

namespace rift::lower {

namespace {

/// Whether the runtime walks the sub-orbits <sub> of <outer> without the
/// map's marks: <outer> is one sub-orbit, or <sub> lies inside an <outer> of
/// at most two links (rift/generated/sub_orbits.hpp, walks_without_marks).
bool walks_without_marks(const std::vector<int>& outer, const std::vector<int>& sub) {
  return orbit_contains(sub, outer) || (orbit_contains(outer, sub) && outer.size() <= 2);
}

}  // namespace

CriterionPlan plan_criterion(const ast::Criterion& crit, const std::vector<ast::Param>& rule_params,
                             const resolve::Symbols& symbols, const check::ExprTypes& types) {
  CriterionPlan plan;
  plan.criterion = &crit;
  ir::Body& body = plan.body;
  body.nodes.push_back(crit.dart.text);
  for (const ast::CriterionNode& n : crit.nodes) {
    PatternNode node;
    // The latest node of that name (resolve/ reports a duplicate).
    for (std::size_t k = body.nodes.size(); k-- > 0;) {
      if (body.nodes[k] == n.from.text) {
        node.from = static_cast<int>(k);
        break;
      }
    }
    node.hops = n.hops;
    node.loc = n.path_loc;
    for (std::size_t k = 0; k < body.nodes.size(); ++k) {
      if (static_cast<int>(k) != node.from || node.hops.size() != 1)
        node.distinct_from.push_back(static_cast<int>(k));
    }
    plan.pattern.push_back(std::move(node));
    body.nodes.push_back(n.name.text);
  }
  ExprLowering lowering(body.graph, body.nodes, nullptr, symbols, types);
  for (const ast::Let& let : crit.lets) {
    const int index = static_cast<int>(body.lets.size());
    body.lets.push_back({let.name.text, lowering.lower(*let.value), let.value->loc});
    lowering.add_let(&let, index);
    ir::Stmt s;
    s.kind = ir::Stmt::Kind::Let;
    s.let = index;
    s.loc = let.value->loc;
    body.stmts.push_back(s);
  }
  plan.measure = lowering.lower_as(*crit.measure->args[0], ir::Type::Real);
  plan.threshold = lowering.lower_as(*crit.measure->args[1], ir::Type::Real);
  for (const ast::ApplyArg& a : crit.apply_args) {
    ir::Type to = types.of(*a.value);
    for (const ast::Param& p : rule_params) {
      if (p.name.text == a.name.text) to = p.type;
    }
    plan.payload.push_back(
        {a.name.text, to, plan.payload_reals, lowering.lower_as(*a.value, to), a.value->loc});
    plan.payload_reals += ast::payload_reals(to);
  }
  plan.guards = measure_guards(body, plan.measure, plan.threshold, crit.measure->op, crit.params);
  std::vector<ir::ExprId*> roots = {&plan.measure, &plan.threshold};
  for (ir::ExprId& guard : plan.guards)
    roots.push_back(&guard);
  for (PayloadField& f : plan.payload)
    roots.push_back(&f.value);
  share_common_subexpressions(body, roots);
  std::vector<ir::ExprId> values;
  values.reserve(roots.size() + body.lets.size());
  for (const ir::ExprId* r : roots)
    values.push_back(*r);
  for (const ir::Let& l : body.lets)
    values.push_back(l.value);
  plan.memos = plan_orbit_memos(body, values, crit.orbit.dims, [&symbols](const std::string& name) {
    const ast::Embedding* e = symbols.embedding(name);
    return e ? e->orbit.dims : std::vector<int>{};
  });
  // Memos and the map's marks are state of the whole map: the cells are
  // collected on every core only without them.
  plan.parallel_collect = plan.memos.empty();
  for (std::size_t i = 0; i < body.graph.size(); ++i) {
    const ir::Node& n = body.graph[static_cast<ir::ExprId>(i)];
    if (n.op == ir::Op::Fold && !walks_without_marks(n.outer, n.orbit))
      plan.parallel_collect = false;
  }
  return plan;
}

void lets_read(const ir::Body& body, ir::ExprId root, std::vector<bool>& used) {
  if (root == ir::kNoExpr) return;
  ir::visit(body.graph, root, [&](const ir::Node& n) {
    if (n.op != ir::Op::Let || n.index < 0) return;
    const auto i = static_cast<std::size_t>(n.index);
    if (used[i]) return;
    used[i] = true;
    lets_read(body, body.lets[i].value, used);
  });
}

}  // namespace rift::lower
