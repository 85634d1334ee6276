// Damaged input never crashes or hangs riftc and always gets a located
// diagnostic: every golden case and every pack of rules/ is truncated at many
// points and has random bytes written into it. Also: every pack of rules/
// compiles cleanly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "driver/compile.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> rule_files(const fs::path& root, const std::string& name_filter) {
  std::vector<fs::path> files;
  if (!fs::exists(root)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() == ".rules" &&
        (name_filter.empty() || entry.path().filename() == name_filter)) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Every error line names a file, a line and a column.
void expect_located(const rift::driver::Result& r, const std::string& what) {
  static const std::regex located(R"(^[^:\s]+:\d+:\d+: (error|warning|note): .+)");
  std::istringstream lines(r.diagnostics);
  std::string line;
  bool any_error = false;
  while (std::getline(lines, line)) {
    if (line.find(": error: ") == std::string::npos) continue;
    any_error = true;
    EXPECT_TRUE(std::regex_match(line, located)) << what << ": unlocated diagnostic: " << line;
  }
  EXPECT_EQ(any_error, r.exit_code == 1) << what << "\n" << r.diagnostics;
}

std::vector<fs::path> all_inputs() {
  std::vector<fs::path> files = rule_files(RIFT_GOLDEN_DIR, "case.rules");
  for (const auto& f : rule_files(RIFT_RULES_DIR, ""))
    files.push_back(f);
  return files;
}

TEST(Robustness, TruncatedInputGetsLocatedDiagnostics) {
  const auto files = all_inputs();
  ASSERT_GT(files.size(), 40u);
  for (const fs::path& file : files) {
    const std::string text = read(file);
    const std::size_t step = std::max<std::size_t>(1, text.size() / 23);
    for (std::size_t cut = 0; cut < text.size(); cut += step) {
      const auto r = rift::driver::compile_text(file.string(), text.substr(0, cut), {});
      expect_located(r, file.string() + " cut at " + std::to_string(cut));
    }
  }
}

TEST(Robustness, RandomBytesGetLocatedDiagnostics) {
  std::mt19937 rng(20260101);  // fixed seed: failures are reproducible
  const auto files = all_inputs();
  for (const fs::path& file : files) {
    const std::string text = read(file);
    if (text.empty()) continue;
    for (int round = 0; round < 8; ++round) {
      std::string damaged = text;
      for (int k = 0; k < 1 + round; ++k) {
        damaged[rng() % damaged.size()] = static_cast<char>(rng() % 256);
      }
      const auto r = rift::driver::compile_text(file.string(), damaged, {});
      expect_located(r, file.string() + " round " + std::to_string(round));
    }
  }
}

TEST(Robustness, DimensionsOutOfRangeAreReported) {
  for (const char* dim : {"4", "-1", "99999999999"}) {
    const std::string text =
        std::string("pack t dimension ") + dim + ";\nembedding p : real on <0>;\n";
    const auto r = rift::driver::compile_text("t.rules", text, {});
    EXPECT_EQ(r.exit_code, 1) << dim;
    expect_located(r, dim);
  }
}

TEST(Robustness, DeepNestingDoesNotCrash) {
  std::string expr;
  for (int k = 0; k < 2000; ++k)
    expr += "(";
  expr += "1";
  for (int k = 0; k < 2000; ++k)
    expr += ")";
  const auto r = rift::driver::compile_text(
      "t.rules", "pack t dimension 2;\nparam x : int = " + expr + ";\n", {});
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
}

TEST(Robustness, HostileNestingIsRejectedWithoutExhaustingTheStack) {
  const std::string deep = std::string(100000, '-') + "1";
  const auto r = rift::driver::compile_text(
      "t.rules", "pack t dimension 2;\nparam x : int = " + deep + ";\n", {});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.diagnostics.find("t.rules:2:"), std::string::npos);
  EXPECT_NE(r.diagnostics.find("nested too deeply"), std::string::npos);
  const std::string fine = std::string(200, '-') + "1";
  EXPECT_EQ(rift::driver::compile_text("t.rules",
                                       "pack t dimension 2;\nparam x : int = " + fine + ";\n", {})
                .exit_code,
            0);
}

TEST(RulePacks, EveryPackInRulesCompiles) {
  const auto packs = rule_files(RIFT_RULES_DIR, "");
  ASSERT_FALSE(packs.empty());
  for (const fs::path& pack : packs) {
    rift::driver::Options options;
    options.inputs = {pack.string()};
    const auto r = rift::driver::compile(options);
    EXPECT_EQ(r.exit_code, 0) << pack << "\n" << r.diagnostics;
    EXPECT_EQ(r.diagnostics, "") << pack;
  }
}

}  // namespace
