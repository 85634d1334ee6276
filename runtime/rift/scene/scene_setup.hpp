// Turns a validated scene into a ready simulation: loads and places the mesh,
// declares and initialises the packs' embeddings, sets masses and pins, and
// binds the interactions and criteria the scene names.
#pragma once

#include <memory>

#include "rift/mesh/assemble.hpp"
#include "rift/pack/pack.hpp"
#include "rift/scene/scene.hpp"
#include "rift/sim/simulation.hpp"

namespace rift {

struct SetupReport {
  AssemblyReport assembly;
  std::size_t pinned_vertices = 0;
  std::size_t held_vertices = 0;  ///< by [[handle]] tables
  std::size_t notch_cuts = 0;     ///< edges (2D) or faces (3D) separated by notches
  Real total_mass = 0;
  /// Components that cannot act on this mesh (inert_components.hpp): an
  /// interaction whose pattern matches no element, such as `corotational`, a
  /// tetrahedron, on hexahedra, and criteria that read only forces no
  /// interaction of the scene stores here.
  std::vector<std::string> warnings;
};

struct SetupOptions {
  bool check_each_rewrite = false;
};

/// Throws InputError (file and line of the scene) for a scene that cannot be
/// set up: a component that no pack offers for the mesh's dimension, pins
/// that match nothing, a mesh with zero area; MeshError for a broken mesh.
std::unique_ptr<Simulation> build_simulation(const Scene& scene, const PackRegistry& packs,
                                             const SetupOptions& options = {},
                                             SetupReport* report = nullptr);

/// Applies the scene's scale, rotation (degrees about x, then y, then z) and
/// translation to every point.
void place_mesh(MeshData& mesh, const SceneMesh& placement);

}  // namespace rift
