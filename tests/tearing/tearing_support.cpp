#include "tearing_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <tuple>

#include <unistd.h>

#include "rift/core/state_embeddings.hpp"
#include "rift/scene/scene.hpp"
#include "rift/scene/scene_setup.hpp"

namespace rift::tearing_test {

std::unique_ptr<Simulation> simulate(const std::string& name, const std::string& toml,
                                     bool check_each_rewrite, SetupReport* report) {
  SetupOptions options;
  options.check_each_rewrite = check_each_rewrite;
  return simulate(name, toml, options, report);
}

std::unique_ptr<Simulation> simulate(const std::string& name, const std::string& toml,
                                     const SetupOptions& options, SetupReport* report) {
  // The process id keeps tests that CTest runs at the same time (one process
  // each) from writing the same file while another reads it.
  const std::string path =
      ::testing::TempDir() + "rift_tearing_" + name + "_" + std::to_string(::getpid()) + ".toml";
  std::ofstream(path) << toml;
  const Scene scene = read_scene(path, standard_packs().catalog());
  std::remove(path.c_str());  // the scene is read: leave no file per process behind
  return build_simulation(scene, standard_packs(), options, report);
}

std::string static_scene(const std::string& mesh, const std::string& scale, double total_mass,
                         const std::string& components) {
  return "[mesh]\nsource = \"" + mesh + "\"\nscale = " + scale +
         "\n[simulation]\nintegrator = \"rk4\"\ndt = 1e-7\nsteps = 1\ngravity = [0, 0, 0]\n"
         "[mass]\ntotal = " +
         std::to_string(total_mass) + "\n" + components;
}

std::string interaction_table(const std::string& name, const std::string& params) {
  return "[[interaction]]\nname = \"" + name + "\"\n" + params + "\n";
}

std::string criterion_table(const std::string& name, double threshold, const std::string& more) {
  return "[[criterion]]\nname = \"" + name + "\"\nthreshold = " + std::to_string(threshold) + "\n" +
         more + "\n";
}

void deform(Simulation& sim, const std::function<Vec3(const Vec3&)>& f) {
  const GMap& g = sim.map();
  g.for_each_cell(Orbit::cell(0, g.dimension()),
                  [&](Dart d) { sim.position()[d] = f(sim.position()[d]); });
}

std::unique_ptr<Simulation> step_once(const std::string& name, const std::string& toml,
                                      Vec3 (*deformation)(const Vec3&)) {
  auto sim = simulate(name, toml);
  deform(*sim, deformation);
  sim->step();
  EXPECT_TRUE(sim->map().check_validity().empty());
  return sim;
}

long Counts::euler() const {
  return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(faces) -
         static_cast<long>(volumes);
}

Counts counts(const GMap& map) {
  Counts c;
  c.vertices = map.count_cells_of_dimension(0);
  c.edges = map.count_cells_of_dimension(1);
  c.faces = map.count_cells_of_dimension(2);
  if (map.dimension() == 3) c.volumes = map.count_cells_of_dimension(3);
  c.components = map.count_cells(Orbit::all(map.dimension()));
  return c;
}

std::vector<Vec3> split_positions(const Simulation& sim) {
  std::map<std::tuple<long long, long long, long long>, int> seen;
  const GMap& g = sim.map();
  g.for_each_cell(Orbit::cell(0, g.dimension()), [&](Dart d) {
    const Vec3& p = sim.position()[d];
    ++seen[{std::llround(p.x() * 1e9), std::llround(p.y() * 1e9), std::llround(p.z() * 1e9)}];
  });
  std::vector<Vec3> out;
  for (const auto& [key, n] : seen) {
    if (n > 1) {
      out.emplace_back(static_cast<Real>(std::get<0>(key)) * 1e-9,
                       static_cast<Real>(std::get<1>(key)) * 1e-9,
                       static_cast<Real>(std::get<2>(key)) * 1e-9);
    }
  }
  return out;
}

std::vector<Vec3> element_centres(const Simulation& sim) {
  const GMap& g = sim.map();
  const int dim = g.dimension();
  std::vector<Vec3> out;
  g.for_each_cell(Orbit::cell(dim, dim), [&](Dart d) {
    Vec3 sum = Vec3::Zero();
    int n = 0;
    g.for_each_sub_orbit(d, Orbit::cell(dim, dim), Orbit::cell(0, dim), [&](Dart v) {
      sum += sim.position()[v];
      ++n;
    });
    out.push_back(sum / n);
  });
  return out;
}

void store_forces(Simulation& sim) {
  std::vector<Vec3> f(sim.position().values().size(), Vec3::Zero());
  const ForceInput in{sim.position().values().data(), sim.velocity().values().data()};
  for (const auto& model : sim.force_models())
    model->clear_accumulated();  // the per-vertex sums of `store +=`, as the simulation does
  for (const auto& model : sim.force_models())
    model->add_forces(in, f.data(), true);
  // The total internal force per vertex, where a pack declares it (as the
  // simulation stores it: same orbit as position, so the same slots).
  if (Embedding<Vec3> total = sim.map().embedding<Vec3>(state::kVertexForce)) {
    std::vector<Vec3>& out = total.values();
    std::copy(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(std::min(f.size(), out.size())),
              out.begin());
  }
}

std::vector<Dart> apply_first_candidate(Simulation& sim, std::size_t c) {
  std::vector<TearCandidate> candidates;
  sim.criteria().at(c)->collect(sim.map(), candidates);
  std::vector<Dart> touched;
  if (candidates.empty()) return touched;
  EXPECT_TRUE(sim.criteria()[c]->apply(sim.map(), candidates.front(), touched));
  EXPECT_TRUE(sim.map().check_validity().empty());
  sim.on_topology_changed(touched);
  return touched;
}

Vec3 shear_and_stretch(const Vec3& p) {
  return Vec3(1.2 * p.x() + 0.1 * p.y() * p.y(), 1.1 * p.y() + 0.05 * p.x(),
              p.z() + 0.03 * p.x() * p.y());
}

bool tear_once(Simulation& sim, std::size_t c) {
  std::vector<TearCandidate> candidates;
  sim.criteria().at(c)->collect(sim.map(), candidates);
  std::vector<Dart> touched;
  for (const TearCandidate& candidate : candidates) {
    touched.clear();
    if (!sim.criteria()[c]->apply(sim.map(), candidate, touched)) continue;
    EXPECT_EQ(sim.map().check_validity(), std::vector<std::string>{});
    sim.on_topology_changed(touched);
    return true;
  }
  return false;
}

}  // namespace rift::tearing_test
