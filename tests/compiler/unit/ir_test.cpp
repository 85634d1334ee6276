// The typed IR of interaction bodies (ir/expr.hpp, ir/body.hpp): what
// `lower` records for a later pass (lets and whens in source order, explicit
// promotions and overloads, positions and velocities as slot reads of pattern
// vertices) and that the IR can be transformed (a pass appends nodes).
#include <gtest/gtest.h>

#include <string>

#include "driver/compile.hpp"
#include "ir/body.hpp"

namespace {

using rift::ir::ExprId;
using rift::ir::Op;
using rift::ir::Type;

const char* kSpring = R"(pack spring dimension 2;
embedding position : vec3 on <1,2>;
embedding velocity : vec3 on <1,2>;
embedding rest_length : real on <0> = 0.0;
embedding f_spring : vec3 on <> = vec3(0, 0, 0);

interaction spring on <0> (k : real > 0 = 2.0, c : real >= 0 = 0.0) {
  pattern { a : <>; b : <>; a -0- b; }
  init rest_length(a) = norm(b.position - a.position);
  let d = b.position - a.position;
  let l = norm(d);
  when l > 0;
  let u = d / l;
  let t = k * (l - a.rest_length) + c * dot(b.velocity - a.velocity, u);
  force a.f_spring = t * u;
  force b.f_spring = -t * u;
  energy 0.5 * k * (l - a.rest_length) * (l - a.rest_length);
}
)";

TEST(Ir, InteractionBodyIsLoweredInSourceOrder) {
  const auto lowered = rift::driver::lower_text("spring.rules", kSpring);
  ASSERT_TRUE(lowered.ok) << lowered.diagnostics;
  ASSERT_EQ(lowered.interactions.size(), 1u);
  const rift::ir::Body& b = lowered.interactions[0].body;
  ASSERT_EQ(b.nodes.size(), 2u);
  EXPECT_EQ(b.nodes[0], "a");
  EXPECT_EQ(b.nodes[1], "b");
  // let d, let l, when, let u, let t: in the order written.
  ASSERT_EQ(b.stmts.size(), 5u);
  EXPECT_EQ(b.stmts[2].kind, rift::ir::Stmt::Kind::When);
  EXPECT_EQ(b.lets[static_cast<std::size_t>(b.stmts[3].let)].name, "u");
  // `l > 0`: the int literal is promoted by lowering, not by the renderer.
  EXPECT_EQ(rift::ir::to_text(b.graph, b.stmts[2].cond, b.nodes), "(l > 0)");
  const rift::ir::Node& cmp = b.graph[b.stmts[2].cond];
  EXPECT_EQ(b.graph[cmp.b].type, Type::Real);
  EXPECT_EQ(b.graph[cmp.a].op, Op::Let);
  EXPECT_EQ(b.graph[cmp.a].index, 1);
  // Positions are slot reads of pattern vertices.
  const rift::ir::Node& d = b.graph[b.lets[0].value];
  EXPECT_EQ(d.op, Op::Sub);
  EXPECT_EQ(d.type, Type::Vec3);
  const rift::ir::Node& xb = b.graph[d.a];
  EXPECT_EQ(xb.op, Op::Position);
  EXPECT_EQ(xb.place.node, 1);
  EXPECT_GE(xb.place.slot, 0);
  EXPECT_TRUE(lowered.interactions[0].kernel.slots[static_cast<std::size_t>(xb.place.slot)].vertex);
  EXPECT_EQ(rift::ir::to_text(b.graph, b.lets[3].value, b.nodes),
            "((k * (l - a.rest_length)) + (c * dot((b.velocity - a.velocity), u)))");
  ASSERT_EQ(b.forces.size(), 2u);
  EXPECT_EQ(b.nodes[static_cast<std::size_t>(b.forces[1].node)], "b");
  EXPECT_EQ(rift::ir::to_text(b.graph, b.forces[1].value, b.nodes), "((-t) * u)");
  ASSERT_NE(b.energy, rift::ir::kNoExpr);
  EXPECT_EQ(b.graph[b.energy].type, Type::Real);
  // The init reads through the map, not through slots.
  ASSERT_EQ(lowered.interactions[0].inits.size(), 1u);
  const auto& init = lowered.interactions[0].inits[0];
  EXPECT_EQ(rift::ir::to_text(b.graph, init.value, b.nodes), "norm((b.position - a.position))");
  EXPECT_EQ(b.graph[b.graph[b.graph[init.value].a].a].place.slot, -1);
}

TEST(Ir, APassCanAppendNodes) {
  const auto lowered = rift::driver::lower_text("spring.rules", kSpring);
  ASSERT_TRUE(lowered.ok) << lowered.diagnostics;
  rift::ir::Graph g = lowered.interactions[0].body.graph;  // a pass works on its copy
  const auto& b = lowered.interactions[0].body;
  const std::size_t before = g.size();
  // d/dl of (l - rest)^2 / 2 written as new nodes over the old ones.
  const ExprId l = b.graph[b.stmts[2].cond].a;
  const ExprId twice = g.binary(Op::Mul, Type::Real, g.real(2.0), l);
  EXPECT_EQ(g.size(), before + 2);
  EXPECT_EQ(rift::ir::to_text(g, twice, b.nodes), "(2 * l)");
  int lets = 0;
  rift::ir::visit(g, b.lets[3].value, [&](const rift::ir::Node& n) { lets += n.op == Op::Let; });
  EXPECT_EQ(lets, 2);  // l and u, each once as written
}

TEST(Ir, BuiltinsRoundTripTheirNames) {
  rift::ir::Builtin fn{};
  ASSERT_TRUE(rift::ir::builtin_from_name("max_eigenvalue", fn));
  EXPECT_EQ(rift::ir::builtin_name(fn), "max_eigenvalue");
  EXPECT_FALSE(rift::ir::builtin_from_name("spring", fn));
}

}  // namespace
