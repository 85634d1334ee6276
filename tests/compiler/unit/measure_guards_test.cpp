// Which conditions of a criterion's measure riftc turns into guards, and
// where collect() tests them (lower/measure_guards.hpp): a condition whose
// failure leaves a value that cannot pass the threshold, tested as soon as
// the lets it reads exist, before the lets only the rest reads.
#include <gtest/gtest.h>

#include <string>

#include "generated_text.hpp"

namespace {

const char* kPack = R"(pack guarded dimension 2;
embedding position : vec3 on <1,2>;
embedding weight : real on <0,1> = 1.0;

rule keep {
  hook a;
  left  { a : <0,2>; }
  right { a : <0,2>; }
}

criterion lazy on <0,2>(a) (threshold : real > 0 = 1.0) {
  node b = a@2;
  let u = a@1@0.position - a.position;
  let w = b@1@0.position - a.position;
  let across = cross(u, w);
  let l = norm(across);
  measure (if dot(u, u) > 1.0 and dot(w, w) > 1.0 and l > 0.0 then dot(u, across) / l
           else 0.0) > threshold;
  apply keep at a;
}

criterion literal on <0,2>(a) () {
  let u = a@1@0.position - a.position;
  measure (if a.weight > 0.5 then norm(u) else 0.0) > 0.25;
  apply keep at a;
}

criterion any_sign on <0,2>(a) (threshold : real = 1.0) {
  let u = a@1@0.position - a.position;
  measure (if a.weight > 0.5 then norm(u) else 0.0) > threshold;
  apply keep at a;
}

criterion below on <0,2>(a) (threshold : real > 0 = 1.0) {
  let u = a@1@0.position - a.position;
  measure (if a.weight > 0.5 then norm(u) else 0.0) < threshold;
  apply keep at a;
}

criterion zero_passes on <0,2>(a) (threshold : real >= 0 = 1.0) {
  let u = a@1@0.position - a.position;
  measure (if a.weight > 0.5 then norm(u) else 0.0) >= threshold;
  apply keep at a;
}

criterion else_positive on <0,2>(a) (threshold : real > 0 = 1.0) {
  let u = a@1@0.position - a.position;
  measure (if a.weight > 0.5 then norm(u) else 2.0) > threshold;
  apply keep at a;
}
)";

std::string collect_of(const char* criterion) {
  static const std::string code =
      rift::compiler_test::generated_text("guarded.rules", kPack, "guarded.cpp");
  return rift::compiler_test::function_text(code, std::string(criterion) + "Criterion::collect(");
}

std::size_t at(const std::string& text, const std::string& what) {
  const std::size_t p = text.find(what);
  EXPECT_NE(p, std::string::npos) << what << " in:\n" << text;
  return p;
}

TEST(MeasureGuards, EachConditionIsTestedBeforeTheLetsOnlyTheLaterOnesRead) {
  const std::string c = collect_of("Lazy");
  ASSERT_FALSE(c.empty());
  // dot(u, u) > 1 reads u only: the cell is left before w is computed.
  EXPECT_LT(at(c, "if (!guard0) return;"), at(c, "const rift::Vec3 l_w ="));
  EXPECT_LT(at(c, "if (!guard1) return;"), at(c, "const rift::Vec3 l_across ="));
  // l > 0 with l = norm(across) is tested without the square root, taken
  // only for the cells that pass every guard.
  EXPECT_LT(at(c, "const bool guard2 = ((l_across).dot(l_across) > 0.0);"),
            at(c, "const rift::Real l_l = (l_across).norm();"));
  EXPECT_LT(at(c, "if (!guard2) return;"), at(c, "const rift::Real measure ="));
}

TEST(MeasureGuards, ALiteralThresholdTheElseValueFailsGivesGuards) {
  const std::string c = collect_of("Literal");
  ASSERT_FALSE(c.empty());
  EXPECT_NE(c.find("if (!guard0) return;"), std::string::npos) << c;
}

TEST(MeasureGuards, NoGuardWhereTheElseValueMayPass) {
  // A threshold of any sign, a comparison a lower bound says nothing of,
  // 0 >= a threshold that may be 0, and an else value above the bound.
  for (const char* name : {"AnySign", "Below", "ZeroPasses", "ElsePositive"}) {
    const std::string c = collect_of(name);
    ASSERT_FALSE(c.empty()) << name;
    EXPECT_EQ(c.find("guard"), std::string::npos) << name << ":\n" << c;
  }
}

}  // namespace
