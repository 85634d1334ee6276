#include "fuzz_harness.hpp"

namespace rift::fuzz {

std::vector<Target> targets() {
  return {
      {"obj", run_obj},     {"gmsh", run_gmsh}, {"medit", run_medit},
      {"vtu", run_vtu},     {"vtk", run_vtk},   {"scene", run_scene},
#ifdef RIFT_FUZZ_WITH_COMPILER
      {"rules", run_rules},
#endif
  };
}

}  // namespace rift::fuzz
