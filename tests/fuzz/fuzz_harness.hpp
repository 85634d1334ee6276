// What each fuzz target checks on one input, shared by the libFuzzer entry
// points (clang, tests/fuzz/*_fuzz.cpp) and by the corpus replay test that the
// ordinary build runs (tests/fuzz/corpus_replay_test.cpp), so that every
// input once found to crash stays a regression test with any compiler.
//
// The contract for any input: either a result that is sound (a valid G-map,
// a scene that names its mesh) or an InputError naming the file and the
// problem. Anything else (another exception, an invalid map, a diagnostic
// without "error") is a bug, reported by throwing FuzzFinding; under
// libFuzzer an uncaught exception aborts, which saves the input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rift::fuzz {

/// A broken contract: the input found a bug.
class FuzzFinding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// One fuzz target: its name (the folder of its corpus and dictionary) and
/// the check run on one input.
struct Target {
  const char* name;
  void (*run)(std::string_view input);
};

void run_obj(std::string_view input);
void run_gmsh(std::string_view input);
void run_medit(std::string_view input);
void run_vtu(std::string_view input);
void run_vtk(std::string_view input);
void run_scene(std::string_view input);
#ifdef RIFT_FUZZ_WITH_COMPILER
void run_rules(std::string_view input);
#endif

/// Every target this build has, in a fixed order.
std::vector<Target> targets();

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace rift::fuzz
