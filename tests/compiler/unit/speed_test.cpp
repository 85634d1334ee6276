// riftc handles a pack of 50 rules (and their interactions) in well under a
// second, generation included.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "driver/compile.hpp"

namespace {

std::string big_pack(int rules) {
  std::string text = R"(pack big dimension 2;
embedding position : vec3 on <1,2> merge mean;
embedding corner_mass : real on <1> = 0.0;
embedding vertex_mass : real on <1,2> = 0.0 merge sum;
embedding f : vec3 on <> = vec3(0, 0, 0);
)";
  for (int k = 0; k < rules; ++k) {
    const std::string n = std::to_string(k);
    text += "rule tri" + n + R"((s : real) {
  left  { n0 : <0,1>; }
  right {
    n0 : <0,_>;  n1 : <_,2>;  n2 : <1,2>;
    n0 -1- n1 -0- n2;
    n2.position = s * mean position over <0,1>(n0);
  }
  when norm(n0.position) > s;
  update n2.vertex_mass = sum corner_mass over <1,2>(n2);
}
interaction spring)" +
            n + R"( on <0> {
  pattern { a : <>; b : <>; a -0- b; }
  let d = b.position - a.position;
  force a.f = d;
  force b.f = -d;
  energy dot(d, d);
}
)";
  }
  return text;
}

TEST(Speed, FiftyRulesCompileInWellUnderASecond) {
  const std::string text = big_pack(50);
  const auto dir = std::filesystem::temp_directory_path() / "riftc_speed_test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "big.rules";
  std::ofstream(file) << text;
  rift::driver::Options options;
  options.inputs = {file.string()};
  options.out_dir = (dir / "out").string();
  const auto start = std::chrono::steady_clock::now();
  const auto result = rift::driver::compile(options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(result.exit_code, 0) << result.diagnostics;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "big.cpp"));
  EXPECT_LT(seconds, 0.5);
  std::filesystem::remove_all(dir);
}

}  // namespace
