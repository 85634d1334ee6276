// Every input of every fuzz target's corpus (seeds and the inputs that once
// crashed, under tests/fuzz/corpus/<target>/) through the target's checks, in
// the ordinary build: a fixed crash that comes back fails here, without
// clang or libFuzzer.
#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_harness.hpp"

namespace rift::fuzz {
// GoogleTest names a parameter by this instead of its bytes.
inline void PrintTo(const Target& target, std::ostream* out) {
  *out << target.name;
}
}  // namespace rift::fuzz

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return std::move(out).str();
}

class CorpusReplay : public ::testing::TestWithParam<rift::fuzz::Target> {};

TEST_P(CorpusReplay, EveryInputKeepsTheContract) {
  const rift::fuzz::Target target = GetParam();
  const fs::path dir = fs::path(RIFT_FUZZ_DIR) / "corpus" / target.name;
  ASSERT_TRUE(fs::is_directory(dir)) << dir << " is missing";
  std::vector<fs::path> inputs;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file()) inputs.push_back(entry.path());
  }
  std::sort(inputs.begin(), inputs.end());
  // A corpus of one or two files would hardly guide the fuzzer.
  EXPECT_GE(inputs.size(), 3u) << dir;
  for (const fs::path& input : inputs) {
    SCOPED_TRACE(input.string());
    const std::string bytes = read_bytes(input);
    try {
      target.run(bytes);
    } catch (const std::exception& e) {
      ADD_FAILURE() << target.name << " on " << input << ": " << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fuzz, CorpusReplay, ::testing::ValuesIn(rift::fuzz::targets()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
