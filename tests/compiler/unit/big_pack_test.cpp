// riftc compiles a pack of 50 rules and their interactions, generation
// included. How fast is measured by the benchmark BM_RiftcCompile
// (tests/bench/riftc_bench.cpp), not here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "big_pack.hpp"
#include "driver/compile.hpp"

namespace {

TEST(BigPack, FiftyRulesCompileAndGenerate) {
  // Per process: ctest runs the tests of this binary side by side.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("riftc_big_pack_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "big.rules";
  std::ofstream(file) << rift::test::big_pack(50);
  rift::driver::Options options;
  options.inputs = {file.string()};
  options.out_dir = (dir / "out").string();
  const auto result = rift::driver::compile(options);
  EXPECT_EQ(result.exit_code, 0) << result.diagnostics;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "big.cpp"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "big.hpp"));
  std::filesystem::remove_all(dir);
}

}  // namespace
