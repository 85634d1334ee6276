// Turns a validated scene into a ready simulation: loads and places the mesh,
// declares and initialises the packs' embeddings, sets masses and pins, and
// binds the interactions and criteria the scene names.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rift/mesh/assemble.hpp"
#include "rift/pack/pack.hpp"
#include "rift/scene/scene.hpp"
#include "rift/sim/setup_phases.hpp"
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
  /// The set-up's phases in order, timed from build_simulation's start
  /// (mesh, assembly, pack inits, masses, notches / handles / loads, then
  /// Simulation::initialise's, then the checks that give warnings): they
  /// cover the whole set-up.
  SetupPhases phases;
};

struct SetupOptions {
  bool check_each_rewrite = false;
  /// The embeddings the frame outputs write when they exist (FrameOptions'
  /// point_arrays and cell_arrays): an interaction storing one of them keeps
  /// storing it although no criterion reads it.
  std::vector<std::string> output_arrays = {"velocity", "force", "point_index"};
  /// The caller rewrites the map itself after the set-up (and announces it
  /// with Simulation::on_topology_changed). Otherwise a scene without
  /// criteria is set up for a map that is never rewritten
  /// (SimulationSettings::rewrites = false), keeping none of what only
  /// re-matching reads.
  bool rewrites_by_hand = false;
};

/// The stored forces a scene reads: those its `criteria` read
/// (ComponentSpec::reads) and `output_arrays`. An interaction of the scene
/// stores its forces only when one of them is read, and a stored-force column
/// that no storing interaction of the scene writes gets no storage: it reads
/// as its default (issue 12, lean memory). build_simulation does both.
std::vector<std::string> stored_forces_read(const Catalog& catalog,
                                            const std::vector<std::string>& criteria,
                                            const std::vector<std::string>& output_arrays);
/// Whether interaction `name` stores its forces when `read` are read.
bool interaction_stores_forces(const Catalog& catalog, const std::string& name,
                               const std::vector<std::string>& read);
/// Withholds the storage (GMap::withhold_storage) of every stored-force
/// column of the catalog that none of `interactions` stores when `read` are read.
void withhold_unstored_forces(GMap& map, const Catalog& catalog,
                              const std::vector<std::string>& interactions,
                              const std::vector<std::string>& read);

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
