// The packs of rules/ as a simulator would use them: declared, initialised,
// forces computed, a criterion evaluated and its rule applied, on a cloth
// grid — the map stays valid and the cloth tears where it is stretched.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "criteria2d.hpp"
#include "mass_spring2d.hpp"
#include "rift/gmap/state_columns.hpp"
#include "rift/io/load_map.hpp"
#include "rift/mesh/map_statistics.hpp"
#include "rift/sim/mass_model.hpp"

namespace {

namespace cloth = rift::packs::criteria2d;
using rift::Vec3;

/// The interactions' inits run when they are initialised, as in a simulation;
/// masses come from the runtime's mass model (density 1), as a scene sets them.
void initialise(rift::GMap& g, std::vector<std::unique_ptr<rift::ForceModel>>& models) {
  const cloth::Pack pack;
  pack.initialise(g);
  const rift::packs::mass_spring2d::Pack springs;
  springs.initialise(g);
  // The masses are the runtime's state: it creates their columns, whether a
  // pack reads them or not.
  auto corner = rift::state_embedding<rift::Real>(g, rift::state::kCornerMass);
  rift::assign_corner_masses_by_density(g, 1.0, corner, g.embedding<rift::Vec3>("position"));
  auto vertex = rift::state_embedding<rift::Real>(g, rift::state::kVertexMass);
  rift::update_all_vertex_masses(g, corner, vertex);
  for (const char* name : {"stretch", "shear"}) {
    rift::ComponentUse use;
    use.name = name;
    models.push_back(springs.make_interaction(use));
    models.back()->initialise(g);
  }
}

TEST(StandardPacks, InitialisersGiveMassesAndRestLengths) {
  rift::GMap g = rift::load_map("grid:quad:4x4");
  std::vector<std::unique_ptr<rift::ForceModel>> models;
  initialise(g, models);
  auto corner = g.embedding<rift::Real>("corner_mass");
  auto vertex = g.embedding<rift::Real>("vertex_mass");
  auto rest = g.embedding<rift::Real>("stretch_rest");
  rift::Real total_corner = 0;
  g.for_each_cell(rift::Orbit{1}, [&](rift::Dart c) { total_corner += corner[c]; });
  // Each quad (area 1/16, density 1) spreads its mass over its corners.
  EXPECT_NEAR(total_corner, 1.0, 1e-12);
  rift::Real total_vertex = 0;
  g.for_each_cell(rift::Orbit{1, 2}, [&](rift::Dart v) { total_vertex += vertex[v]; });
  EXPECT_NEAR(total_vertex, 1.0, 1e-12);
  g.for_each_dart([&](rift::Dart d) { EXPECT_NEAR(rest[d], 0.25, 1e-12); });
}

// global_edge names the dart across its edge (`node b = a@2`): a boundary
// edge gives no candidate, an inner edge of a flat sheet the closed form of
// eq. (5), |(f_A + f_B) . n| with n the unit normal of the edge in the sheet.
TEST(StandardPacks, GlobalEdgeMatchesInnerEdgesWithTheirClosedForm) {
  rift::GMap g = rift::load_map("grid:quad:3x3");
  std::vector<std::unique_ptr<rift::ForceModel>> models;
  initialise(g, models);
  auto position = g.embedding<Vec3>("position");
  auto vertex_force = g.embedding<Vec3>("vertex_force");
  // A force that differs from vertex to vertex, in the sheet's plane and out of it.
  g.for_each_cell(rift::Orbit{1, 2}, [&](rift::Dart v) {
    const Vec3& p = position[v];
    vertex_force[v] = Vec3(1.0 + 2.0 * p.x(), -0.5 + p.y() * p.x(), 3.0);
  });
  const rift::Real threshold = 1e-9;
  cloth::GlobalEdgeCriterion criterion(cloth::GlobalEdgeParams{threshold});
  criterion.initialise(g);
  std::vector<rift::TearCandidate> candidates;
  criterion.collect(g, candidates);
  std::vector<rift::Dart> inner_edges;
  g.for_each_cell(rift::Orbit{0, 2}, [&](rift::Dart a) {
    if (!g.is_free(a, 2)) inner_edges.push_back(a);
  });
  ASSERT_EQ(inner_edges.size(), 12u);  // of the 24 edges of a 3x3 grid, 12 are inner
  ASSERT_EQ(candidates.size(), inner_edges.size());
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const rift::Dart a = candidates[k].at;
    EXPECT_EQ(a, inner_edges[k]);  // in the cells' order
    const Vec3& pa = position[a];
    const Vec3& pb = position[g.alpha(a, 0)];
    const Vec3 n = Vec3(0.0, 0.0, 1.0).cross(pb - pa).normalized();
    const rift::Real expected = std::abs((vertex_force[a] + vertex_force[g.alpha(a, 0)]).dot(n));
    EXPECT_NEAR(candidates[k].measure + threshold, expected, 1e-12) << "edge of dart " << a;
  }
}

TEST(StandardPacks, StretchedClothTearsAndStaysValid) {
  rift::GMap g = rift::load_map("grid:quad:4x4");
  std::vector<std::unique_ptr<rift::ForceModel>> models;
  initialise(g, models);
  const auto before = rift::compute_statistics(g);
  auto position = g.embedding<Vec3>("position");
  // Pull the upper half of the cloth up: the springs across y = 0.5 stretch.
  for (auto& p : position.values()) {
    if (p.y() > 0.49) p.y() += 0.5;
  }
  auto velocity = g.embedding<Vec3>("velocity");
  const rift::ForceInput in{position.values().data(), velocity.values().data()};
  std::vector<Vec3> f(position.values().size(), Vec3::Zero());
  for (auto& m : models)
    m->add_forces(in, f.data(), true);
  // The simulator stores the total internal force per vertex (global_edge reads it).
  auto vertex_force = g.embedding<Vec3>("vertex_force");
  std::copy(f.begin(), f.end(), vertex_force.values().begin());
  EXPECT_GT(models[0]->potential_energy(in), 0.0);
  cloth::GlobalEdgeCriterion criterion(cloth::GlobalEdgeParams{1.0});
  criterion.initialise(g);
  std::vector<rift::TearCandidate> candidates;
  criterion.collect(g, candidates);
  EXPECT_GT(candidates.size(), 0u);
  std::vector<rift::Dart> touched;
  std::size_t applied = 0;
  for (const auto& c : candidates)
    applied += criterion.apply(g, c, touched) ? 1 : 0;
  EXPECT_GT(applied, 0u);
  const auto problems = g.check_validity();
  EXPECT_TRUE(problems.empty()) << problems.front();
  const auto after = rift::compute_statistics(g);
  EXPECT_EQ(after.darts, before.darts);
  EXPECT_GT(after.boundary, before.boundary);
  EXPECT_GT(after.vertices, before.vertices);
  // The runtime recomputes the mass of every vertex a rewrite touched, as
  // Simulation::on_topology_changed does: the darts the rules report must
  // reach every split vertex, which then weighs the corners it kept (§4.1).
  auto vertex = g.embedding<rift::Real>("vertex_mass");
  auto corner = g.embedding<rift::Real>("corner_mass");
  for (rift::Dart d : touched) {
    if (g.is_alive(d)) rift::update_vertex_mass(g, d, corner, vertex);
  }
  g.for_each_cell(rift::Orbit{1, 2}, [&](rift::Dart v) {
    rift::Real sum = 0;
    std::vector<rift::Slot> seen;  // each corner once
    g.for_each_in_orbit(v, rift::Orbit{1, 2}, [&](rift::Dart x) {
      const rift::Slot s = corner.slot(x);
      if (std::find(seen.begin(), seen.end(), s) == seen.end()) {
        seen.push_back(s);
        sum += corner[x];
      }
    });
    EXPECT_NEAR(vertex[v], sum, 1e-12);
  });
}

}  // namespace
