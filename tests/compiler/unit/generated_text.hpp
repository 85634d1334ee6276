// What riftc generates from a pack given as text, read back for tests that
// check the shape of the generated C++.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "driver/compile.hpp"

namespace rift::compiler_test {

/// The text of `file` (e.g. "memos.cpp"), one of the files riftc writes for
/// the pack `text` named `rules_name` (e.g. "memos.rules"), without #line
/// directives. Compiled into a folder of this process's own: ctest runs a
/// binary's tests as processes side by side, and a shared folder was removed
/// under a neighbour's feet.
inline std::string generated_text(const std::string& rules_name, const char* text,
                                  const std::string& file) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() /
      ("riftc_" + fs::path(rules_name).stem().string() + "_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  rift::driver::Options options;
  options.out_dir = dir.string();
  options.line_directives = false;
  const auto r = rift::driver::compile_text(rules_name, text, options);
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
  std::ifstream in(dir / file);
  std::ostringstream s;
  s << in.rdbuf();
  in.close();
  fs::remove_all(dir);
  return s.str();
}

/// The text of a generated function, from its signature to the next one.
inline std::string function_text(const std::string& code, const std::string& signature) {
  const std::size_t start = code.find(signature);
  if (start == std::string::npos) return {};
  return code.substr(start, code.find("\n}\n", start) - start);
}

}  // namespace rift::compiler_test
