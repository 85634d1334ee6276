// Helpers of the tearing tests: scenes of the standard packs built from TOML
// text, imposed deformations, and the counts a torn map is checked against.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rift/gmap/gmap.hpp"
#include "rift/pack/pack.hpp"
#include "rift/scene/scene_setup.hpp"
#include "rift/sim/simulation.hpp"
#include "standard_packs.hpp"

namespace rift::tearing_test {

using test_support::standard_packs;

/// A simulation of the scene `toml` (written to a temporary file named after
/// `name`), checking the G-map after every rewrite unless told otherwise
/// (a test that checks it itself).
std::unique_ptr<Simulation> simulate(const std::string& name, const std::string& toml,
                                     bool check_each_rewrite = true, SetupReport* report = nullptr);
/// The same with set-up options of the test's choosing.
std::unique_ptr<Simulation> simulate(const std::string& name, const std::string& toml,
                                     const SetupOptions& options, SetupReport* report = nullptr);

/// The TOML of a static scene: no gravity, a tiny dt (one step barely moves
/// anything), `total_mass` spread over `mesh` scaled by `scale`, then the
/// given [[interaction]] and [[criterion]] tables.
std::string static_scene(const std::string& mesh, const std::string& scale, double total_mass,
                         const std::string& components);

/// An [[interaction]] table: its name, then `params` (TOML lines).
std::string interaction_table(const std::string& name, const std::string& params);

/// A [[criterion]] table with its threshold, then `more` (TOML lines).
std::string criterion_table(const std::string& name, double threshold,
                            const std::string& more = "");

/// Moves every vertex to f(position), after the rest state was recorded.
void deform(Simulation& sim, const std::function<Vec3(const Vec3&)>& f);

/// Builds the scene, imposes `deformation`, runs one step (its criteria
/// apply), and checks that the map is valid.
std::unique_ptr<Simulation> step_once(const std::string& name, const std::string& toml,
                                      Vec3 (*deformation)(const Vec3&));

struct Counts {
  std::size_t vertices = 0, edges = 0, faces = 0, volumes = 0, components = 0;
  /// V - E + F (- C in 3D).
  long euler() const;
};
Counts counts(const GMap& map);

/// Positions (rounded to 1e-9) shared by more than one vertex orbit: where vertices were split.
std::vector<Vec3> split_positions(const Simulation& sim);

/// Centres of the cells of dimension `dim` (faces in 2D, volumes in 3D).
std::vector<Vec3> element_centres(const Simulation& sim);

/// Every interaction computes and stores its forces at the current state,
/// and vertex_force their sum where a pack declares it, as the first stage
/// of a step does (criteria read them). No external forces.
void store_forces(Simulation& sim);

/// The first candidate of criterion `c`, applied by hand as the simulation
/// would (rematch included); returns the touched darts.
std::vector<Dart> apply_first_candidate(Simulation& sim, std::size_t c = 0);

/// A smooth deformation that strains every edge of a unit mesh differently
/// (x and y stretched and sheared, z bent): candidates everywhere.
Vec3 shear_and_stretch(const Vec3& p);

/// Applies the first candidate of criterion c whose rule applies (a split at
/// a vertex with nothing to split does not), checks the map, then tells the
/// simulation, as its loop does. False when none applies.
bool tear_once(Simulation& sim, std::size_t c);

}  // namespace rift::tearing_test
