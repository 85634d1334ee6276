// riftc's front end and checks on one .rules text, as `riftc --check` would
// run them (no code generated).
#include <string>

#include "driver/compile.hpp"
#include "fuzz_harness.hpp"

namespace rift::fuzz {

void run_rules(std::string_view input) {
  // Includes are looked up next to this path, which does not exist: an
  // include in the input is reported as unreadable rather than reading the disk.
  const std::string path = "fuzz-rules/input.rules";
  const driver::Result result = driver::compile_text(path, std::string(input), {});
  if (result.exit_code != 0 && result.exit_code != 1) {
    throw FuzzFinding("exit code " + std::to_string(result.exit_code));
  }
  // A failure must say where: "fuzz-rules/input.rules:LINE:COL: error: ...".
  if (result.exit_code == 1 && result.diagnostics.find(path + ":") == std::string::npos) {
    throw FuzzFinding("failed without a located error message:\n" + result.diagnostics);
  }
}

}  // namespace rift::fuzz
