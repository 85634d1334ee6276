// Common subexpressions (lower/share.cpp, emit/ir_render.cpp): a value the
// rules write several times is computed once, at the level where its inputs
// exist; a fold's body computes what does not depend on the fold's dart once,
// before the fold. Checked on the IR (equal expressions are one node) and on
// the generated C++ (how many times a computation is written, and where).
#include <gtest/gtest.h>

#include <string>

#include "generated_text.hpp"
#include "ir/body.hpp"

namespace {

const char* kPack = R"(pack sharing dimension 2;
embedding position : vec3 on <1,2>;
embedding velocity : vec3 on <1,2>;
embedding vertex_force : vec3 on <1,2>;
embedding face_weight : real on <0,1> = 0.0;
embedding rest_length : real on <0> = 0.0;
embedding f_spring : vec3 on <> = vec3(0, 0, 0);

interaction spring on <0> (k : real > 0 = 2.0) {
  pattern { a : <>; b : <>; a -0- b; }
  let l = norm(b.position - a.position);
  when l > 0;
  force a.f_spring = k * (l - a.rest_length) * (b.position - a.position) / l;
  force b.f_spring = -k * (l - a.rest_length) * (b.position - a.position) / l;
  energy 0.5 * k * (l - a.rest_length) * (l - a.rest_length);
}

rule mark {
  hook a;
  left  { a : <0,1>; }
  right { a : <0,1>; }
}

criterion heavy on <1,2>(v) (threshold : real > 0 = 1.0) {
  let area = sum of (if norm(cross(f@0.position - f.position, f@1@0.position - f.position)) > 0.0
                     then norm(cross(f@0.position - f.position, f@1@0.position - f.position))
                          * (sum of c.face_weight for each <1>(c) in <0,1>(f))
                          * (sum of c.face_weight for each <1>(c) in <0,1>(f))
                          * (sum of c.face_weight for each <1>(c) in <0,1>(f))
                          * (threshold * threshold)
                     else 0.0)
             for each <0,1>(f) in <1,2>(v);
  measure area > threshold;
  apply mark at v;
}
)";

std::string generated_source() {
  return rift::compiler_test::generated_text("sharing.rules", kPack, "sharing.cpp");
}

std::string function(const std::string& code, const std::string& signature) {
  return rift::compiler_test::function_text(code, signature);
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(Sharing, EqualExpressionsOfABodyAreOneNode) {
  const auto lowered = rift::driver::lower_text("sharing.rules", kPack);
  ASSERT_TRUE(lowered.ok) << lowered.diagnostics;
  const rift::ir::Body& b = lowered.interactions[0].body;
  ASSERT_EQ(b.sharing.fold_vars.size(), b.graph.size());
  // energy = ((0.5 * k) * s) * s with s = l - a.rest_length: both operands are one node,
  // which the forces use too.
  const rift::ir::Node& outer = b.graph[b.energy];
  const rift::ir::Node& inner = b.graph[outer.a];
  EXPECT_EQ(outer.b, inner.b);
  EXPECT_EQ(rift::ir::to_text(b.graph, outer.b, b.nodes), "(l - a.rest_length)");
  std::vector<rift::ir::ExprId> roots = {b.energy};
  for (const rift::ir::Force& f : b.forces)
    roots.push_back(f.value);
  // Twice in the energy (by two products), once in each force.
  EXPECT_EQ(rift::ir::count_uses(b.graph, roots)[static_cast<std::size_t>(outer.b)], 4);
  // Each node is there once.
  for (rift::ir::ExprId i = 0; i < static_cast<rift::ir::ExprId>(b.graph.size()); ++i) {
    for (rift::ir::ExprId j = 0; j < i; ++j) {
      const auto& x = b.graph[i];
      const auto& y = b.graph[j];
      const bool same = x.op == y.op && x.type == y.type && x.a == y.a && x.b == y.b &&
                        x.c == y.c && x.more == y.more && x.op != rift::ir::Op::Literal &&
                        x.name == y.name && x.place.node == y.place.node &&
                        x.place.hops == y.place.hops && x.place.slot == y.place.slot &&
                        x.fn == y.fn && x.index == y.index && x.embedding == y.embedding;
      EXPECT_FALSE(same) << "nodes " << j << " and " << i << ": "
                         << rift::ir::to_text(b.graph, i, b.nodes);
    }
  }
}

TEST(Sharing, ForceKernelComputesARepeatedValueOnce) {
  const std::string evaluate = function(generated_source(), "::evaluate(");
  ASSERT_FALSE(evaluate.empty());
  // (l - a.rest_length) is written three times in the body: once in the
  // forces' branch, once in the energy's; the edge vector, four times: once.
  EXPECT_EQ(count(evaluate, "(l_l - "), 2) << evaluate;
  EXPECT_EQ(count(evaluate, "] - in.x["), 1) << evaluate;
}

TEST(Sharing, CriterionComputesEachFaceTermOnceAndHoistsWhatTheFoldDoesNotChange) {
  const std::string collect = function(generated_source(), "HeavyCriterion::collect(");
  ASSERT_FALSE(collect.empty());
  // The outer fold, and one inner fold (written three times), which only
  // reads an embedding: one call of the runtime's fold_sum.
  EXPECT_EQ(count(collect, "for_each_sub_orbit("), 1) << collect;
  EXPECT_EQ(count(collect, "fold_sum("), 1) << collect;
  // The face's area: once per face.
  EXPECT_EQ(count(collect, ".cross("), 1) << collect;
  // threshold * threshold does not depend on the face: computed before the outer fold.
  const std::size_t product = collect.find("(p_.threshold * p_.threshold)");
  ASSERT_NE(product, std::string::npos) << collect;
  EXPECT_EQ(count(collect, "(p_.threshold * p_.threshold)"), 1) << collect;
  EXPECT_LT(product, collect.find("for_each_sub_orbit(")) << collect;
}

// The same program gives the same text: names follow the body, not the
// order in which the compiler that built riftc evaluates operands.
TEST(Sharing, GeneratedCodeIsDeterministic) {
  EXPECT_EQ(generated_source(), generated_source());
}

}  // namespace
