// Every generated interaction of the physics packs: forces are minus the
// gradient of the energy (central differences), the support orbits match the
// counts of docs/physics.md §4, and the forces stored in the orbits of
// Table 1's last column add up, vertex by vertex, to the forces the
// integrator uses (each stored value written by exactly one match).
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "physics_setup.hpp"
#include "rift/io/load_map.hpp"

namespace rift::physics_test {
namespace {

struct Case {
  const char* mesh;
  Use interaction;
};

std::vector<Case> cases() {
  return {
      {"grid:mix:3x3", {"stretch", {{"stiffness", 60.0}}}},
      {"grid:mix:3x3", {"shear", {{"stiffness", 43.0}}}},
      {"grid:mix:3x3", {"bend", {{"stiffness", 10.0}}}},
      {"grid:mix:3x3", {"angular_shear", {{"stiffness", 0.5}}}},
      {"grid:mix:3x3", {"angular_bend", {{"stiffness", 0.01}}}},
      {"grid:quad:3x3", {"angular_bend", {{"stiffness", 0.01}}}},
      {"grid:tri:3x3", {"membrane", {{"young", 1000.0}, {"poisson", 0.3}}}},
      {"block:hex:2x2x1", {"stretch", {{"stiffness", 60.0}}}},
      {"block:hex:2x2x1", {"shear", {{"stiffness", 43.0}}}},
      {"block:hex:2x2x1", {"volume_shear", {{"stiffness", 43.0}}}},
      {"block:tet:2x1x1", {"corotational", {{"young", 1000.0}, {"poisson", 0.3}}}},
  };
}

std::unique_ptr<Simulation> deformed(const Case& c, unsigned seed, Real amplitude = 0.05) {
  SimSetup setup;
  setup.settings.gravity = Vec3::Zero();
  setup.interactions = {c.interaction};
  auto sim = simulate(load_map(c.mesh), setup);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> noise(-amplitude, amplitude);
  move_vertices(*sim,
                [&](const Vec3& p) { return Vec3(p + Vec3(noise(rng), noise(rng), noise(rng))); });
  return sim;
}

TEST(Interactions, ForcesAreMinusTheGradientOfTheEnergy) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    auto sim = deformed(c, 7);
    ASSERT_GT(sim->force_models()[0]->active_matches(), 0u);
    const std::vector<Vec3> f = internal_forces(*sim);
    Real largest = 0;
    for (const Vec3& x : f)
      largest = std::max(largest, x.norm());
    ASSERT_GT(largest, 0.0);
    auto& x = sim->position().values();
    const Real h = 1e-6;
    Real worst = 0;
    for (Slot s = 0; s < x.size(); ++s) {
      if (!sim->position().attachment().slot_alive(s)) continue;
      for (int k = 0; k < 3; ++k) {
        const Real keep = x[s][k];
        x[s][k] = keep + h;
        const Real plus = elastic_energy(*sim);
        x[s][k] = keep - h;
        const Real minus = elastic_energy(*sim);
        x[s][k] = keep;
        worst = std::max(worst, std::abs(-(plus - minus) / (2 * h) - f[s][k]));
      }
    }
    EXPECT_LT(worst, 1e-6 * largest) << "largest force " << largest;
  }
}

TEST(Interactions, StoredForcesAddUpToTheVertexForces) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    auto sim = deformed(c, 11);
    // Moving vertices: damping terms are stored too.
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> noise(-0.5, 0.5);
    for (Vec3& v : sim->velocity().values())
      v = Vec3(noise(rng), noise(rng), noise(rng));
    sim->step();  // stores the forces of the state at the start of the step
    const GMap& g = sim->map();
    const int n = g.dimension();
    Real largest = 0, worst = 0;
    g.for_each_cell(Orbit::cell(0, n), [&](Dart vertex) {
      Vec3 gathered = Vec3::Zero();
      for (const auto& att : g.attachments()) {
        (void)att;
      }
      for (const char* name :
           {"f_stretch", "f_shear", "f_bend", "f_ashear", "f_ashear_end", "f_abend", "f_abend_wing",
            "f_membrane", "f_volume_shear", "f_fem"}) {
        const Embedding<Vec3> e = g.embedding<Vec3>(name);
        if (!e) continue;
        std::set<Slot> seen;  // each stored orbit once
        g.for_each_in_orbit(vertex, Orbit::cell(0, n), [&](Dart d) {
          if (seen.insert(e.slot(d)).second) gathered += e[d];
        });
      }
      const Vec3 expected = sim->internal_forces()[sim->position().slot(vertex)];
      largest = std::max(largest, expected.norm());
      worst = std::max(worst, (gathered - expected).norm());
    });
    EXPECT_GT(largest, 0.0);
    EXPECT_LT(worst, 1e-12 * largest);
  }
}

// docs/physics.md §4 for the paper's 10 x 10 grids; angular shear has one
// spring per face corner, angular bending one per interior edge.
TEST(Interactions, SupportOrbitsMatchTheSpringCounts) {
  struct Expected {
    const char* mesh;
    std::size_t stretch, shear_faces, bend, angular_shear, angular_bend;
  };
  for (const Expected& e : {Expected{"grid:quad:10x10", 400, 100, 360, 400, 180},
                            Expected{"grid:tri:10x10", 600, 0, 560, 600, 280},
                            Expected{"grid:mix:10x10", 500, 50, 460, 500, 230}}) {
    SCOPED_TRACE(e.mesh);
    SimSetup setup;
    setup.interactions = {{"stretch", {{"stiffness", 1.0}}},
                          {"shear", {{"stiffness", 1.0}}},
                          {"bend", {{"stiffness", 1.0}}},
                          {"angular_shear", {{"stiffness", 1.0}}},
                          {"angular_bend", {{"stiffness", 1.0}}}};
    auto sim = simulate(load_map(e.mesh), setup);
    const auto& m = sim->force_models();
    EXPECT_EQ(m[0]->active_matches(), e.stretch);
    EXPECT_EQ(m[1]->active_matches(), e.shear_faces);  // two diagonals each
    EXPECT_EQ(m[2]->active_matches(), e.bend);
    EXPECT_EQ(m[3]->active_matches(), e.angular_shear);
    EXPECT_EQ(m[4]->active_matches(), e.angular_bend);
  }
  // 3D: hexahedra get 3D shear, tetrahedra the co-rotational element, not the other way round.
  for (const char* mesh : {"block:hex:2x2x2", "block:tet:2x2x2"}) {
    SCOPED_TRACE(mesh);
    SimSetup setup;
    setup.interactions = {{"volume_shear", {{"stiffness", 1.0}}},
                          {"corotational", {{"young", 1.0}}},
                          {"shear", {{"stiffness", 1.0}}}};
    auto sim = simulate(load_map(mesh), setup);
    const bool hex = std::string(mesh).find("hex") != std::string::npos;
    const auto& m = sim->force_models();
    EXPECT_EQ(m[0]->active_matches(), hex ? 8u : 0u);
    EXPECT_EQ(m[1]->active_matches(), hex ? 0u : 48u);
    EXPECT_EQ(m[2]->active_matches(), hex ? 48u : 0u);  // 6 faces of each hexahedron
  }
}

TEST(Interactions, RestShapeHasNoForce) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    SimSetup setup;
    setup.settings.gravity = Vec3::Zero();
    setup.interactions = {c.interaction};
    auto sim = simulate(load_map(c.mesh), setup);
    for (const Vec3& f : internal_forces(*sim))
      EXPECT_LT(f.norm(), 1e-12);
  }
}

}  // namespace
}  // namespace rift::physics_test
