// Mesh readers: read the text, then build the G-map as `rift info` would,
// and check that the map is valid.
#include <string>

#include "fuzz_harness.hpp"
#include "rift/core/input_error.hpp"
#include "rift/io/readers.hpp"
#include "rift/mesh/assemble.hpp"

namespace rift::fuzz {

namespace {

/// The name messages must carry: a reader that loses it leaves the user
/// without the file to look at.
const std::string kSource = "fuzz-input";

void run_reader(MeshData (*reader)(const std::string&, std::string_view), std::string_view input) {
  try {
    const MeshData mesh = reader(kSource, input);
    const GMap map = assemble_gmap(mesh);
    const std::vector<std::string> problems = map.check_validity(1);
    if (!problems.empty()) throw FuzzFinding("assembled map is invalid: " + problems.front());
  } catch (const InputError& e) {
    if (e.file() != kSource) {
      throw FuzzFinding("message names '" + e.file() + "', not the input: " + e.what());
    }
    if (e.problem().empty()) throw FuzzFinding("an error without a message");
  }
}

}  // namespace

void run_obj(std::string_view input) {
  run_reader(io::read_obj, input);
}
void run_gmsh(std::string_view input) {
  run_reader(io::read_gmsh, input);
}
void run_medit(std::string_view input) {
  run_reader(io::read_medit, input);
}
void run_vtu(std::string_view input) {
  run_reader(io::read_vtu, input);
}
void run_vtk(std::string_view input) {
  run_reader(io::read_vtk_legacy, input);
}

}  // namespace rift::fuzz
