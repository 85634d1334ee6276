// The pipeline riftc runs: load/parse -> resolve -> types -> topology ->
// embeddings -> warnings -> (emit). Each stage only adds diagnostics; the
// driver renders them once at the end.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lower/interaction_plan.hpp"

namespace rift::driver {

struct Options {
  std::vector<std::string> inputs;
  std::string out_dir;  // empty: check only
  std::string depfile;  // Make-style dependencies of the generated files (with out_dir)
  std::vector<std::string> disabled_warnings;
  std::vector<std::string> include_dirs;  // searched for includes after the including file's folder
  bool warnings_as_errors = false;
};

struct Result {
  int exit_code = 0;        // 0 success, 1 errors
  std::string diagnostics;  // rendered, sorted
};

Result compile(const Options& options);

/// Compiles in-memory text as if it were the file `path` (tests, fuzzing).
Result compile_text(const std::string& path, const std::string& text, const Options& options);

/// A program through the front end and `lower`, for passes that work on the
/// IR (ir/expr.hpp, ir/body.hpp) and for tests.
struct Lowered {
  bool ok = false;                                   // no error: the plans below are complete
  std::string diagnostics;                           // rendered
  std::vector<lower::InteractionPlan> interactions;  // in declaration order
  std::shared_ptr<const void> keep_alive;            // the AST and checks the plans point into
};

Lowered lower_text(const std::string& path, const std::string& text);

}  // namespace rift::driver
