#include "lower/interaction_plan.hpp"

#include <algorithm>

#include "check/kernels.hpp"
#include "check/topology.hpp"
#include "lower/expr_lower.hpp"
#include "lower/share.hpp"

namespace rift::lower {

namespace {

// The columns a value reads (position and velocity are not columns).
void add_columns_read(const ir::Graph& g, ir::ExprId root, std::set<std::string>& out) {
  ir::visit(g, root, [&](const ir::Node& n) {
    if (n.op == ir::Op::Read) out.insert(n.embedding);
  });
}

}  // namespace

InteractionPlan plan_interaction(const check::CheckedInteraction& ci,
                                 const resolve::Symbols& symbols, const check::ExprTypes& types) {
  const ast::Interaction& inter = *ci.interaction;
  InteractionPlan plan;
  plan.interaction = &inter;
  plan.kernel = plan_kernel(ci, symbols);
  ir::Body& body = plan.body;
  body.nodes = plan.kernel.nodes;

  ExprLowering loop(body.graph, body.nodes, &plan.kernel, symbols, types);
  for (const ast::BodyStmt& st : inter.body) {
    ir::Stmt s;
    if (st.kind == ast::BodyStmt::Kind::Let) {
      const ast::Let& let = inter.lets[st.index];
      const int index = static_cast<int>(body.lets.size());
      body.lets.push_back({let.name.text, loop.lower(*let.value), let.value->loc});
      loop.add_let(&let, index);
      s.kind = ir::Stmt::Kind::Let;
      s.let = index;
      s.loc = let.value->loc;
    } else {
      const ast::Expr& cond = *inter.whens[st.index];
      s.kind = ir::Stmt::Kind::When;
      s.cond = loop.lower(cond);
      s.loc = cond.loc;
    }
    body.stmts.push_back(s);
  }
  for (std::size_t k = 0; k < inter.forces.size(); ++k) {
    const ast::Assign& a = inter.forces[k];
    ir::Force f;
    for (std::size_t v = 0; v < body.nodes.size(); ++v) {
      if (body.nodes[v] == a.node.text) f.node = static_cast<int>(v);
    }
    f.embedding = a.embedding.text;
    f.vertex_slot = plan.kernel.forces[k].vertex_slot;
    f.store_slot = plan.kernel.forces[k].store_slot;
    f.value = loop.lower_as(*a.value, ir::Type::Vec3);
    f.loc = a.value->loc;
    body.forces.push_back(f);
  }
  for (std::size_t k = 0; k < inter.stores.size() + inter.accumulations.size(); ++k) {
    const bool accumulate = k >= inter.stores.size();
    const ast::Assign& a =
        accumulate ? inter.accumulations[k - inter.stores.size()] : inter.stores[k];
    ir::Store st;
    st.accumulate = accumulate;
    for (std::size_t v = 0; v < body.nodes.size(); ++v) {
      if (body.nodes[v] == a.node.text) st.node = static_cast<int>(v);
    }
    st.embedding = a.embedding.text;
    st.store_slot = plan.kernel.stores[k];
    st.value = loop.lower_as(*a.value, symbols.target(a)->type);
    st.loc = a.value->loc;
    body.stores.push_back(st);
  }
  if (inter.energy) body.energy = loop.lower_as(*inter.energy, ir::Type::Real);
  for (const ast::JacobianBlock& a : inter.jacobians) {
    ir::JacobianBlock j;
    for (std::size_t v = 0; v < body.nodes.size(); ++v) {
      if (body.nodes[v] == a.force_node.text) j.node = static_cast<int>(v);
    }
    j.embedding = a.force.text;
    j.by_node = static_cast<int>(std::find(body.nodes.begin(), body.nodes.end(), a.by_node.text) -
                                 body.nodes.begin());
    j.by_slot = plan.kernel.find(j.by_node, {}, vertex_orbit(ci.graph.dimension));
    j.velocity = a.by_state.text == check::kVelocityEmbedding;
    j.value = loop.lower_as(*a.value, ir::Type::Mat3);
    j.loc = a.loc;
    body.jacobians.push_back(j);
  }

  // Inits run on the initial map, reading through it rather than through slots.
  ExprLowering at_init(body.graph, body.nodes, nullptr, symbols, types);
  for (const ast::Init& init : inter.inits) {
    InitPlan p;
    for (std::size_t v = 0; v < body.nodes.size(); ++v) {
      if (body.nodes[v] == init.dart.text) p.node = static_cast<int>(v);
    }
    p.embedding = init.embedding.text;
    p.type = symbols.target(init)->type;
    p.value = at_init.lower_as(*init.value, p.type);
    p.loc = init.value->loc;
    plan.inits.push_back(p);
    plan.embeddings.insert(p.embedding);
    add_columns_read(body.graph, p.value, plan.embeddings);
  }

  std::vector<ir::ExprId*> init_roots;
  init_roots.reserve(plan.inits.size());
  for (InitPlan& p : plan.inits)
    init_roots.push_back(&p.value);
  share_common_subexpressions(body, init_roots);

  for (const SlotUse& s : plan.kernel.slots)
    plan.embeddings.insert(s.via);
  for (const ForceStore& f : plan.kernel.forces)
    plan.embeddings.insert(f.embedding);
  for (const ir::Store& st : body.stores)
    plan.embeddings.insert(st.embedding);
  auto loop_reads = [&](ir::ExprId root) {
    if (root != ir::kNoExpr) add_columns_read(body.graph, root, plan.embeddings);
  };
  for (const ir::Let& l : body.lets)
    loop_reads(l.value);
  for (const ir::Stmt& s : body.stmts)
    loop_reads(s.cond);
  for (const ir::Force& f : body.forces)
    loop_reads(f.value);
  for (const ir::Store& st : body.stores)
    loop_reads(st.value);
  for (const ir::JacobianBlock& j : body.jacobians)
    loop_reads(j.value);
  loop_reads(body.energy);
  plan.embeddings.erase("");
  return plan;
}

}  // namespace rift::lower
