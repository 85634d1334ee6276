// Every rule-language code block of the language reference, the tutorials
// and the README compiles (issue 9, deliverable 5). A fenced block's info
// string says what it is:
//
//   ```rules                 a whole .rules file: riftc must accept it;
//   ```rules 2d / rules 3d   declarations: compiled after the line
//                            `pack doc dimension N; include "commonNd.rules";`
//                            (the standard packs' shared embeddings);
//   ```rules fragment: WHY   not compilable on its own (a grammar outline, a
//                            piece of a larger declaration): skipped, and WHY
//                            must say why.
//
// A block without an info string that looks like rule code (a line starting
// with `pack`, `rule`, `interaction`, `embedding`, ...) fails the test: it
// must say which of the three it is. riftc runs with -Werror and the
// standard packs' folder as include path; its messages are reported at the
// documentation's file and line.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Block {
  int first_line = 0;  // the line after the opening fence
  std::string info;    // the info string after ```
  std::string text;
};

std::vector<Block> fenced_blocks(const std::string& path) {
  std::ifstream in(path);
  std::vector<Block> blocks;
  std::string line;
  int number = 0;
  bool inside = false;
  const std::regex fence(R"(^\s*```(.*)$)");
  while (std::getline(in, line)) {
    ++number;
    std::smatch m;
    if (std::regex_match(line, m, fence)) {
      if (!inside) {
        blocks.push_back({number + 1, m[1], ""});
      }
      inside = !inside;
    } else if (inside) {
      blocks.back().text += line + "\n";
    }
  }
  return blocks;
}

struct RiftcRun {
  int status = 0;
  std::string output;
};

RiftcRun run_riftc(const std::string& command) {
  RiftcRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return {-1, "cannot run " + command};
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr)
    r.output += buffer.data();
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// riftc's messages about `scratch`, moved to the documentation's lines.
std::string at_doc_lines(const std::string& output, const std::string& scratch,
                         const std::string& doc, int first_line, int shift) {
  std::string out;
  const std::regex located(
      std::regex_replace(scratch, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
      R"(:([0-9]+):)");
  std::istringstream lines(output);
  for (std::string l; std::getline(lines, l);) {
    std::smatch m;
    if (std::regex_search(l, m, located)) {
      const int line = std::stoi(m[1]) - shift + first_line - 1;
      l = m.prefix().str() + doc + ":" + std::to_string(line) + ":" + m.suffix().str();
    }
    out += l + "\n";
  }
  return out;
}

class DocBlocks : public ::testing::TestWithParam<const char*> {};

TEST_P(DocBlocks, EveryRulesBlockCompiles) {
  const std::string doc = GetParam();
  const std::string path = std::string(RIFT_SOURCE_DIR) + "/" + doc;
  const std::vector<Block> blocks = fenced_blocks(path);
  ASSERT_FALSE(blocks.empty()) << path << " has no code block (or is missing)";
  const std::regex rule_code(
      R"((^|\n)\s*(pack|rule|interaction|criterion|embedding|script|init|param|let|measure|force)\s)");
  int compiled = 0;
  for (const Block& b : blocks) {
    const std::string where = doc + ":" + std::to_string(b.first_line - 1);
    std::istringstream info(b.info);
    std::string language, mode, reason;
    info >> language >> mode;
    if (!mode.empty() && mode.back() == ':') mode.pop_back();  // ```rules fragment: WHY
    std::getline(info, reason);
    if (language.empty()) {
      EXPECT_FALSE(std::regex_search(b.text, rule_code))
          << where << ": this block looks like rule code: open it with ```rules (a whole "
          << "file), ```rules 2d / ```rules 3d (declarations) or ```rules fragment: WHY";
      continue;
    }
    if (language != "rules") continue;
    if (mode == "fragment") {
      EXPECT_NE(reason.find_first_not_of(" \t"), std::string::npos)
          << where << ": a ```rules fragment must say why it is not compiled";
      continue;
    }
    std::string prefix;
    if (mode == "2d" || mode == "3d") {
      const std::string n = mode.substr(0, 1);
      prefix = "pack doc dimension " + n + "; include \"common" + n + "d.rules\";\n";
    } else {
      EXPECT_TRUE(mode.empty()) << where << ": unknown ```rules mode '" << mode << "'";
    }
    const std::string scratch = ::testing::TempDir() + "rift_doc_block_" +
                                std::to_string(b.first_line) + "_" +
                                doc.substr(doc.rfind('/') + 1) + ".rules";
    std::ofstream(scratch) << prefix << b.text;
    const RiftcRun r = run_riftc(std::string("'") + RIFTC + "' '" + scratch + "' -Werror -I '" +
                                 RIFT_SOURCE_DIR + "/rules'");
    EXPECT_EQ(r.status, 0) << where << ": this ```rules block does not compile:\n"
                           << at_doc_lines(r.output, scratch, doc, b.first_line,
                                           prefix.empty() ? 0 : 1);
    ++compiled;
  }
  std::cout << doc << ": " << compiled << " rules blocks compiled\n";
}

INSTANTIATE_TEST_SUITE_P(Docs, DocBlocks,
                         ::testing::Values("docs/language.md", "docs/tutorial.md",
                                           "docs/tutorial-criterion.md", "README.md"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                           std::string name = param.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

/// The three docs with rule code keep some compiled blocks: a file whose
/// blocks all became fragments would pass the test above vacuously.
TEST(DocBlocks, TheReferenceAndTutorialsHaveCompiledBlocks) {
  for (const char* doc : {"docs/language.md", "docs/tutorial.md", "docs/tutorial-criterion.md"}) {
    int compiled = 0;
    for (const Block& b : fenced_blocks(std::string(RIFT_SOURCE_DIR) + "/" + doc)) {
      if (b.info.rfind("rules", 0) == 0 && b.info.find("fragment") == std::string::npos) ++compiled;
    }
    EXPECT_GE(compiled, 1) << doc;
  }
}

}  // namespace
