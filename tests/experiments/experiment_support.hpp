// Helpers of the experiment tests: scenes from TOML text with the standard
// packs, rest positions by mesh point, and which edges or faces tore.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rift/pack/pack.hpp"
#include "rift/scene/scene_setup.hpp"
#include "rift/sim/simulation.hpp"
#include "standard_packs.hpp"

namespace rift::experiment_test {

using test_support::standard_packs;

/// Writes `toml` to a temporary file named after `name` and reads it.
Scene scene_of(const std::string& name, const std::string& toml);
/// The simulation of a scene (G-map checked after every rewrite).
std::unique_ptr<Simulation> simulate(const Scene& scene, SetupReport* report = nullptr);

/// The sides (edges in 2D, faces in 3D) as sets of mesh point indices.
using Side = std::vector<std::int64_t>;
/// Every free side (the boundary).
std::set<Side> free_sides(const Simulation& sim);

/// Mesh point positions at the start, by point index.
std::map<std::int64_t, Vec3> rest_points(const Simulation& sim);

/// The centres (at rest) of the free sides not in `before`: what tore since.
std::vector<Vec3> torn_centres(const Simulation& sim, const std::set<Side>& before,
                               const std::map<std::int64_t, Vec3>& rest);
/// The torn edges (2D) as rest-position segments.
std::vector<std::pair<Vec3, Vec3>> torn_edges(const Simulation& sim, const std::set<Side>& before,
                                              const std::map<std::int64_t, Vec3>& rest);

/// Steps until the first tear (or `max_steps`); returns the steps done.
long steps_to_first_tear(Simulation& sim, long max_steps);

/// True when every position and velocity is finite and within `bound`.
bool bounded(const Simulation& sim, Real bound);

}  // namespace rift::experiment_test
