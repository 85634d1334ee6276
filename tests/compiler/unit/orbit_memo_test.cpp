// Orbit memos (lower/orbit_memo.cpp): which values of a criterion's
// collection riftc computes once per orbit, checked on the generated C++ of
// criteria that fold over each vertex's faces. A value that depends on more
// than the face's orbit (a hop, the vertex, a let, a per-dart value the
// walk's choice of dart changes) or that no other cell reaches must be
// computed where it is written.
#include <gtest/gtest.h>

#include <string>

#include "generated_text.hpp"

namespace {

const char* kPack = R"(pack memos dimension 2;
embedding position : vec3 on <1,2>;
embedding face_weight : real on <0,1> = 0.0;
embedding vertex_weight : real on <1,2> = 0.0;
embedding corner_weight : real on <1> = 0.0;
embedding dart_weight : real on <> = 0.0;

rule mark {
  hook a;
  left  { a : <0,1>; }
  right { a : <0,1>; }
}

criterion shared on <1,2>(v) (threshold : real > 0 = 1.0) {
  measure sum of (sum face_weight over <0,1>(f)) * (max of c.corner_weight * threshold
                                                    for each <1>(c) in <0,1>(f))
          for each <0,1>(f) in <1,2>(v) > threshold;
  apply mark at v;
}

criterion hop on <1,2>(v) (threshold : real > 0 = 1.0) {
  measure sum of sum face_weight over <0,1>(f@2) for each <0,1>(f) in <1,2>(v) > threshold;
  apply mark at v;
}

criterion reads_vertex on <1,2>(v) (threshold : real > 0 = 1.0) {
  measure sum of (sum of c.corner_weight + v.vertex_weight for each <1>(c) in <0,1>(f))
          for each <0,1>(f) in <1,2>(v) > threshold;
  apply mark at v;
}

criterion per_dart on <1,2>(v) (threshold : real > 0 = 1.0) {
  measure sum of (sum of c.dart_weight for each <1>(c) in <0,1>(f))
          for each <0,1>(f) in <1,2>(v) > threshold;
  apply mark at v;
}

criterion reads_let on <1,2>(v) (threshold : real > 0 = 1.0) {
  let w = v.vertex_weight;
  measure sum of (sum of c.corner_weight * w for each <1>(c) in <0,1>(f))
          for each <0,1>(f) in <1,2>(v) > threshold;
  apply mark at v;
}

criterion inside_the_cell on <0,1,2>(x) (threshold : real > 0 = 1.0) {
  measure sum of sum face_weight over <0,1>(f) for each <0,1>(f) in <0,1,2>(x) > threshold;
  apply mark at x;
}
)";

std::string generated(const std::string& file) {
  return rift::compiler_test::generated_text("memos.rules", kPack, file);
}

std::string function(const std::string& code, const std::string& signature) {
  return rift::compiler_test::function_text(code, signature);
}

TEST(OrbitMemo, AFaceValueOfAVertexCriterionIsReadThroughTheMemo) {
  const std::string code = generated("memos.cpp");
  const std::string collect = function(code, "SharedCriterion::collect(");
  ASSERT_FALSE(collect.empty()) << code;
  EXPECT_NE(collect.find("memo0_.begin(g, rift::Orbit{0, 1});"), std::string::npos) << collect;
  // One entry per face visit, both face values read through it (the inner
  // fold reads a parameter: constant in a collection).
  EXPECT_NE(collect.find("memo0_.entry(g, d_f, rift::Orbit{0, 1})"), std::string::npos) << collect;
  EXPECT_NE(collect.find("memo0_0_.get(memo0_, memo0_entry, 0,"), std::string::npos) << collect;
  EXPECT_NE(collect.find("memo0_1_.get(memo0_, memo0_entry, 1,"), std::string::npos) << collect;
  // apply() matches the rule on a map earlier tears changed: never memoised.
  EXPECT_EQ(function(code, "SharedCriterion::apply(").find("memo"), std::string::npos);
  const std::string header = generated("memos.hpp");
  EXPECT_NE(header.find("mutable rift::generated::OrbitMemo memo0_;"), std::string::npos);
}

TEST(OrbitMemo, ValuesThatDependOnMoreThanTheOrbitAreNotMemoised) {
  const std::string code = generated("memos.cpp");
  for (const char* name : {"Hop", "ReadsVertex", "PerDart", "ReadsLet", "InsideTheCell"}) {
    const std::string collect = function(code, std::string(name) + "Criterion::collect(");
    ASSERT_FALSE(collect.empty()) << name;
    EXPECT_EQ(collect.find("memo"), std::string::npos) << name << ":\n" << collect;
  }
}

}  // namespace
