#include "experiment_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace rift::experiment_test {

Scene scene_of(const std::string& name, const std::string& toml) {
  const std::string path = ::testing::TempDir() + "rift_experiment_" + name + ".toml";
  std::ofstream(path) << toml;
  return read_scene(path, standard_packs().catalog());
}

std::unique_ptr<Simulation> simulate(const Scene& scene, SetupReport* report) {
  SetupOptions options;
  options.check_each_rewrite = true;
  return build_simulation(scene, standard_packs(), options, report);
}

std::set<Side> free_sides(const Simulation& sim) {
  const GMap& g = sim.map();
  const int n = g.dimension();
  const Embedding<std::int64_t> point = g.embedding<std::int64_t>("point_index");
  std::set<Side> sides;
  const Orbit side = n == 2 ? Orbit{0} : Orbit{0, 1};
  g.for_each_cell(side, [&](Dart d) {
    if (!g.is_free(d, n)) return;
    Side s;
    g.for_each_in_orbit(d, side, [&](Dart x) { s.push_back(point[x]); });
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    sides.insert(s);
  });
  return sides;
}

std::map<std::int64_t, Vec3> rest_points(const Simulation& sim) {
  std::map<std::int64_t, Vec3> rest;
  const GMap& g = sim.map();
  const Embedding<std::int64_t> point = g.embedding<std::int64_t>("point_index");
  g.for_each_cell(Orbit::cell(0, g.dimension()),
                  [&](Dart d) { rest.emplace(point[d], sim.position()[d]); });
  return rest;
}

std::vector<Vec3> torn_centres(const Simulation& sim, const std::set<Side>& before,
                               const std::map<std::int64_t, Vec3>& rest) {
  std::vector<Vec3> out;
  for (const Side& s : free_sides(sim)) {
    if (before.count(s)) continue;
    Vec3 c = Vec3::Zero();
    for (std::int64_t p : s)
      c += rest.at(p);
    out.push_back(c / static_cast<Real>(s.size()));
  }
  return out;
}

std::vector<std::pair<Vec3, Vec3>> torn_edges(const Simulation& sim, const std::set<Side>& before,
                                              const std::map<std::int64_t, Vec3>& rest) {
  std::vector<std::pair<Vec3, Vec3>> out;
  for (const Side& s : free_sides(sim)) {
    if (before.count(s) || s.size() != 2) continue;
    out.emplace_back(rest.at(s[0]), rest.at(s[1]));
  }
  return out;
}

long steps_to_first_tear(Simulation& sim, long max_steps) {
  long done = 0;
  while (done < max_steps && sim.tears() == 0) {
    sim.step();
    ++done;
  }
  return done;
}

bool bounded(const Simulation& sim, Real bound) {
  bool ok = true;
  const GMap& g = sim.map();
  g.for_each_cell(Orbit::cell(0, g.dimension()), [&](Dart d) {
    const Vec3& x = sim.position()[d];
    const Vec3& v = sim.velocity()[d];
    if (!x.allFinite() || !v.allFinite() || x.norm() > bound) ok = false;
  });
  return ok;
}

}  // namespace rift::experiment_test
