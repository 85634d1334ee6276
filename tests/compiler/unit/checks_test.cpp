// The checks, driven in-process: each test states one rule of JERBOA_RULES.md
// and looks for the diagnostic it must produce (or its absence).
#include <gtest/gtest.h>

#include <string>

#include "check/builtins.hpp"
#include "driver/compile.hpp"

namespace {

using rift::driver::compile_text;
using rift::driver::Options;

const char* kHeader = R"(pack t dimension 2;
embedding position : vec3 on <1,2>;
)";

rift::driver::Result check(const std::string& body, const Options& options = {}) {
  return compile_text("t.rules", std::string(kHeader) + body, options);
}

bool mentions(const rift::driver::Result& r, const std::string& text) {
  return r.diagnostics.find(text) != std::string::npos;
}

TEST(Checks, TriangulationIsValid) {
  const auto r = check(R"(rule tri {
  left  { n0 : <0,1>; }
  right { n0 : <0,_>; n1 : <_,2>; n2 : <1,2>; n0 -1- n1 -0- n2;
          n2.position = mean position over <0,1>(n0); }
})");
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
  EXPECT_EQ(r.diagnostics, "");
}

TEST(Checks, TriangulationWithSwappedArcsBreaksACycle) {
  // n1 -0- n2 and n0 -1- n1 swapped in dimension: n1 would carry 0 twice.
  const auto r = check(R"(rule tri {
  left  { n0 : <0,1>; }
  right { n0 : <0,_>; n1 : <_,2>; n2 : <1,2>; n0 -0- n1 -1- n2;
          n2.position = mean position over <0,1>(n0); }
})");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(mentions(r, "dimension 0 is used twice on node 'n0'")) << r.diagnostics;
}

TEST(Checks, RelabellingOntoAdjacentHookLinksBreaksTheCycle) {
  // <0,2> under hook <0,1>: alpha_0 and alpha_2 would mirror the hook's 0- and
  // 1-links, and alpha_0 alpha_1 is not an involution on a face.
  const auto r = check(R"(rule r {
  left  { n0 : <0,1>; n0 -2- n0; }
  right { n0 : <0,2>; n0 -1- n0; }
})");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(
      mentions(r, "node 'n0' lies on a 0-2-0-2 cycle in the left pattern but not in the right one"))
      << r.diagnostics;
}

TEST(Checks, RelabellingOntoDistantHookLinksKeepsTheCycle) {
  // n1's alpha_0 mirrors the hook's alpha_1 and its alpha_2 is a loop: fine.
  const auto r = check(R"(rule r {
  left  { n0 : <0,1>; }
  right { n0 : <0,_>; n1 : <_,0>; n0 -1- n1; n1 -2- n1; }
})");
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
}

TEST(Checks, LoopAndImplicitArcMakeACycle) {
  const auto r = check(R"(rule unsew {
  left  { a : <0,2>; }
  right { a : <0,_>; a -2- a; }
})");
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
}

TEST(Checks, ErrorsAreSortedByLocationAcrossPasses) {
  // A type error (reported by a later pass) comes after a name error that
  // appears earlier in the file, and before a topology error that comes later.
  const auto r = check(R"(rule r {
  left  { a : <0,1>; }
  right { a : <0,1>; }
  when unknown_thing > 0;
  when norm(a.position);
}
rule s { left { f : <0,1>; } right { } }
)");
  const auto first = r.diagnostics.find("unknown name 'unknown_thing'");
  const auto second = r.diagnostics.find("a precondition must be bool");
  const auto third = r.diagnostics.find("deleted node 'f' has no 2-arc");
  ASSERT_NE(first, std::string::npos) << r.diagnostics;
  ASSERT_NE(second, std::string::npos) << r.diagnostics;
  ASSERT_NE(third, std::string::npos) << r.diagnostics;
  EXPECT_LT(first, second);
  EXPECT_LT(second, third);
}

TEST(Checks, WarningsCanBeDisabledOrMadeErrors) {
  const std::string body = "rule r { left { a : <0,1>; } right { a : <0,1>; } let u = 1; }";
  const auto plain = check(body);
  EXPECT_EQ(plain.exit_code, 0);
  EXPECT_TRUE(mentions(plain, "warning: 'u' is never used [-Wunused-variable]"));
  Options off;
  off.disabled_warnings = {"unused-variable"};
  EXPECT_EQ(check(body, off).diagnostics, "");
  Options werror;
  werror.warnings_as_errors = true;
  const auto strict = check(body, werror);
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_TRUE(mentions(strict, "error: 'u' is never used"));
}

TEST(Checks, MergePolicyReplacesTheMergeExpression) {
  const std::string rule = R"(
rule sew { hook a, b;
  left  { a : <0>; b : <0>; a -2- a; b -2- b; }
  right { a : <0>; b : <0>; a -2- b; } })";
  EXPECT_EQ(compile_text("t.rules", "pack t dimension 2;\nembedding p : vec3 on <1,2>;" + rule, {})
                .exit_code,
            1);
  EXPECT_EQ(compile_text("t.rules",
                         "pack t dimension 2;\nembedding p : vec3 on <1,2> merge keep;" + rule, {})
                .exit_code,
            0);
}

TEST(Checks, CreatedNodeTakesTheDeclaredDefault) {
  const std::string rule = R"(
rule ins { left { n0 : <0,2>; } right { n0 : <_,2>; n1 : <1,2>; n0 -0- n1; } })";
  EXPECT_EQ(compile_text("t.rules", "pack t dimension 2;\nembedding m : real on <1,2>;" + rule, {})
                .exit_code,
            1);
  EXPECT_EQ(
      compile_text("t.rules", "pack t dimension 2;\nembedding m : real on <1,2> = 1.0;" + rule, {})
          .exit_code,
      0);
}

TEST(Builtins, OverloadsPreferExactMatchesThenPromoteInts) {
  using rift::ast::Type;
  const auto* abs = rift::check::builtin("abs");
  ASSERT_NE(abs, nullptr);
  EXPECT_EQ(rift::check::select_overload(*abs, {Type::Int})->result, Type::Int);
  EXPECT_EQ(rift::check::select_overload(*abs, {Type::Real})->result, Type::Real);
  const auto* v = rift::check::builtin("vec3");
  EXPECT_EQ(rift::check::select_overload(*v, {Type::Int, Type::Real, Type::Int})->result,
            Type::Vec3);
  EXPECT_EQ(rift::check::select_overload(*v, {Type::Vec3, Type::Real, Type::Int}), nullptr);
  EXPECT_EQ(rift::check::builtin("spring_force"), nullptr);  // built-ins stay generic
}

}  // namespace
