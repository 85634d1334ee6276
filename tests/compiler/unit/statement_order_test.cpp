// Lets and whens of a body run in the order they are written: a `when` guards
// the lets after it. Checked on the generated C++ (the guard's `if` comes
// before the guarded let's definition) and on name visibility (a `when` does
// not see a later let).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "driver/compile.hpp"

namespace {

namespace fs = std::filesystem;

const char* kPack = R"(pack order dimension 2;
embedding position : vec3 on <1,2>;
embedding count_k : int on <1,2> = 0;
embedding velocity : vec3 on <1,2>;
embedding vertex_force : vec3 on <1,2>;
embedding spring_force : vec3 on <> = vec3(0, 0, 0);

rule guarded {
  hook a;
  left  { a : <0,1>; }
  right { a : <0,1>; }
  when a.count_k > 0;
  let q = 10 / a.count_k;
  when q > 1;
}

interaction guarded_spring on <0,2> {
  pattern { a : <>; b : <>; a -0- b; }
  let d = b.position - a.position;
  when a.count_k > 0;
  let k = real(10 / a.count_k);
  force a.spring_force = k * d;
  energy k * dot(d, d);
}
)";

std::string generated_source(const std::string& text) {
  // Per process: ctest runs this binary's tests as processes of their own,
  // side by side, and a shared folder was removed under a neighbour's feet.
  const fs::path dir =
      fs::temp_directory_path() / ("riftc_statement_order_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  rift::driver::Options options;
  options.out_dir = dir.string();
  const auto r = rift::driver::compile_text("order.rules", text, options);
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
  std::ifstream in(dir / "order.cpp");
  std::ostringstream s;
  s << in.rdbuf();
  in.close();
  fs::remove_all(dir);
  return s.str();
}

/// Every occurrence of `guard` before the first definition of `let` that follows it.
void expect_guard_first(const std::string& code, const std::string& function,
                        const std::string& guard, const std::string& let) {
  const std::size_t start = code.find(function);
  ASSERT_NE(start, std::string::npos) << function;
  const std::size_t g = code.find(guard, start);
  const std::size_t l = code.find(let, start);
  ASSERT_NE(g, std::string::npos) << guard << " in " << function;
  ASSERT_NE(l, std::string::npos) << let << " in " << function;
  EXPECT_LT(g, l) << "in " << function << ", the let is evaluated before the when guarding it";
}

TEST(StatementOrder, WhenGuardsTheLetsAfterIt) {
  const std::string code = generated_source(kPack);
  ASSERT_FALSE(code.empty());
  expect_guard_first(code, "bool apply_guarded(", "if (!((e_count_k", "l_q =");
  // The interaction's one body, which the force pass and energy() share.
  expect_guard_first(code, "::evaluate(", "if (!(", "l_k =");
  // ... and the let written before the guard stays before it.
  const std::size_t start = code.find("::evaluate(");
  EXPECT_LT(code.find("l_d =", start), code.find("if (!(", start));
}

TEST(StatementOrder, WhenDoesNotSeeALaterLet) {
  const auto r = rift::driver::compile_text("order.rules", R"(pack order dimension 2;
embedding count_k : int on <1,2> = 0;
rule r {
  hook a;
  left  { a : <0,1>; }
  right { a : <0,1>; }
  when q > 0;
  let q = a.count_k;
}
)",
                                            {});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.diagnostics.find("'q' is used before its 'let'"), std::string::npos) << r.diagnostics;
}

}  // namespace
