// Properties of the whole flow with the generated packs: without external
// force the total momentum (and, undamped, the angular momentum) is
// conserved; scaling lengths, masses, stiffnesses and time consistently
// scales the motion (docs/physics.md §6); tearing never changes the mass.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "physics_setup.hpp"
#include "rift/io/load_map.hpp"

namespace rift::physics_test {
namespace {

Vec3 angular_momentum(const Simulation& sim) {
  Vec3 l = Vec3::Zero();
  sim.map().for_each_cell(Orbit::cell(0, sim.map().dimension()), [&](Dart d) {
    l += sim.vertex_mass()[d] * sim.position()[d].cross(sim.velocity()[d]);
  });
  return l;
}

void shake(Simulation& sim, unsigned seed, Real dx, Real dv) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  move_vertices(sim, [&](const Vec3& p) { return Vec3(p + dx * Vec3(u(rng), u(rng), u(rng))); });
  for (Vec3& v : sim.velocity().values())
    v = dv * Vec3(u(rng), u(rng), u(rng));
}

struct FreeBody {
  const char* mesh;
  std::vector<Use> interactions;
  bool damped;
};

std::vector<FreeBody> free_bodies() {
  const std::vector<Use> springs2d = {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
                                      {"shear", {{"stiffness", 43.0}, {"damping", 0.1}}},
                                      {"bend", {{"stiffness", 10.0}, {"damping", 0.1}}},
                                      {"angular_shear", {{"stiffness", 0.5}, {"damping", 0.01}}},
                                      {"angular_bend", {{"stiffness", 0.01}, {"damping", 0.001}}}};
  std::vector<Use> with_membrane = springs2d;
  with_membrane.push_back({"membrane", {{"young", 200.0}, {"poisson", 0.3}}});
  return {{"grid:mix:6x6", with_membrane, true},
          {"block:hex:2x2x2",
           {{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}},
            {"shear", {{"stiffness", 43.0}, {"damping", 0.1}}},
            {"volume_shear", {{"stiffness", 43.0}, {"damping", 0.1}}}},
           true},
          {"block:tet:2x2x2",
           {{"corotational", {{"young", 2000.0}, {"poisson", 0.3}, {"damping", 0.001}}}},
           true},
          {"block:tet:2x2x2", {{"corotational", {{"young", 2000.0}, {"poisson", 0.3}}}}, false}};
}

TEST(Conservation, MomentumWithoutExternalForce) {
  for (const FreeBody& body : free_bodies()) {
    SCOPED_TRACE(std::string(body.mesh) + (body.damped ? " damped" : " undamped"));
    SimSetup setup;
    setup.settings.dt = 5e-4;
    setup.settings.gravity = Vec3::Zero();
    setup.interactions = body.interactions;
    auto sim = simulate(load_map(body.mesh), setup);
    shake(*sim, 3, 0.03, 0.5);
    const Vec3 p0 = sim->momentum();
    const Vec3 l0 = angular_momentum(*sim);
    const Real scale = sim->total_mass() * 0.5;  // m |v|
    Real moved = 0;
    const std::vector<Vec3> x0 = sim->position().values();
    for (int s = 0; s < 300; ++s)
      sim->step();
    for (std::size_t s = 0; s < x0.size(); ++s)
      moved = std::max(moved, (sim->position().values()[s] - x0[s]).norm());
    EXPECT_GT(moved, 0.01);  // the body did deform and move
    EXPECT_LT((sim->momentum() - p0).norm(), 1e-13 * scale) << sim->momentum().transpose();
    // Every force is central or comes from a rotation-invariant energy: no
    // torque either (the elements' strain-rate damping aside). RK4 keeps a
    // quadratic invariant only to its truncation error, hence the tolerance.
    if (!body.damped || std::string(body.mesh) != "block:tet:2x2x2") {
      EXPECT_LT((angular_momentum(*sim) - l0).norm(), 1e-6 * scale);
    }
  }
}

// docs/physics.md §6: lengths x s, masses x s^3, time x sqrt(s) with the same
// gravity: k x s^2 (N/m), c x s^2.5 (N s/m), angular k x s^4 (N m), membrane
// E x s^2 (N/m), solid E x s (Pa), stiffness-proportional damping x sqrt(s).
TEST(Scaling, LengthsMassesAndStiffnessesScaleTheMotion) {
  struct Body {
    const char* mesh;
    std::vector<std::pair<Use, std::vector<Real>>> interactions;  // parameter exponents of s
    bool hang;
  };
  const Real s = 2, tau = std::sqrt(s);
  const std::vector<Body> bodies = {
      {"grid:mix:6x6",
       {{{"stretch", {{"stiffness", 60.0}, {"damping", 0.1}}}, {2, 2.5}},
        {{"shear", {{"stiffness", 43.0}, {"damping", 0.1}}}, {2, 2.5}},
        {{"bend", {{"stiffness", 10.0}, {"damping", 0.1}}}, {2, 2.5}},
        {{"angular_shear", {{"stiffness", 0.05}, {"damping", 0.001}}}, {4, 4.5}},
        {{"angular_bend", {{"stiffness", 0.001}, {"damping", 0.0001}}}, {4, 4.5}},
        {{"membrane", {{"young", 50.0}, {"poisson", 0.3}, {"damping", 0.001}}}, {2, 0, 0.5}}},
       true},
      {"block:tet:3x1x1",
       {{{"corotational", {{"young", 300.0}, {"poisson", 0.3}, {"damping", 0.002}}}, {1, 0, 0.5}}},
       false}};
  for (const Body& body : bodies) {
    SCOPED_TRACE(body.mesh);
    auto run = [&](Real scale) {
      GMap map = load_map(body.mesh);
      for (Vec3& p : map.embedding<Vec3>("position").values()) {
        p = body.hang ? Vec3(p.x(), 0, p.y()) : p;  // hang the cloth in the x-z plane
        p *= scale;
      }
      SimSetup setup;
      setup.settings.integrator = IntegratorKind::kRK4;
      setup.settings.dt = 5e-4 * std::sqrt(scale);
      for (const auto& [use, exponents] : body.interactions) {
        Use scaled = use;
        for (std::size_t i = 0; i < scaled.params.size(); ++i)
          scaled.params[i].second *= std::pow(scale, exponents[i]);
        setup.interactions.push_back(scaled);
      }
      setup.prepare = [&](Simulation& sim) {
        sim.set_total_mass(0.1 * scale * scale * scale);
        // Pinned along the top (cloth) or the left end (bar).
        sim.pin_where([&](const Vec3& p) {
          return body.hang ? p.z() > scale - 1e-9 && p.x() < 0.5 * scale : p.x() < 1e-9;
        });
      };
      auto sim = simulate(std::move(map), setup);
      for (int i = 0; i < 1000; ++i)
        sim->step();
      return sim;
    };
    auto a = run(1);
    auto b = run(s);
    const auto& xa = a->position().values();
    const auto& xb = b->position().values();
    const auto& va = a->velocity().values();
    const auto& vb = b->velocity().values();
    ASSERT_EQ(xa.size(), xb.size());
    Real moved = 0, dx = 0, dv = 0, vmax = 0;
    for (std::size_t i = 0; i < xa.size(); ++i) {
      moved = std::max(moved, va[i].norm());
      dx = std::max(dx, (xb[i] - s * xa[i]).norm());
      dv = std::max(dv, (vb[i] - (s / tau) * va[i]).norm());
      vmax = std::max(vmax, vb[i].norm());
    }
    EXPECT_GT(moved, 0.01);
    EXPECT_LT(dx, 1e-10 * s);
    EXPECT_LT(dv, 1e-10 * vmax);
    // Energies scale by mu s^2 / tau^2 = s^4.
    EXPECT_NEAR(elastic_energy(*b) / (std::pow(s, 4) * elastic_energy(*a)), 1.0, 1e-9);
  }
}

// The paper's cloth torn by the global edge criterion (criteria2d): every
// rewrite splits vertices and corners, never mass.
TEST(Masses, TotalMassIsTheSumOfVertexMassesAcrossRewrites) {
  for (const char* mesh : {"grid:quad:10x10", "grid:mix:10x10"}) {
    SCOPED_TRACE(mesh);
    GMap map = load_map(mesh);
    for (Vec3& p : map.embedding<Vec3>("position").values())
      p = Vec3(p.x(), 0, p.y());
    SimSetup setup;
    setup.settings.dt = 5e-4;
    setup.settings.check_each_rewrite = true;
    setup.interactions = paper_cloth_springs();
    setup.criteria = {{"global_edge", {{"threshold", 0.02}}}};
    setup.prepare = [](Simulation& sim) {
      sim.set_total_mass(0.1);
      EXPECT_EQ(sim.pin_where([](const Vec3& p) {
        return p.z() > 1 - 1e-9 && (p.x() < 1e-9 || p.x() > 1 - 1e-9);
      }),
                2u);
    };
    auto sim = simulate(std::move(map), setup);
    const Embedding<Real> corner = sim->map().embedding<Real>("corner_mass");
    auto check = [&] {
      EXPECT_NEAR(sum_of_vertex_masses(*sim), 0.1, 1e-14);
      EXPECT_NEAR(sim->total_mass(), 0.1, 1e-14);
      const GMap& g = sim->map();
      g.for_each_cell(Orbit{1, 2}, [&](Dart v) {
        std::set<Slot> corners;
        Real sum = 0;
        g.for_each_in_orbit(v, Orbit{1, 2}, [&](Dart d) {
          if (corners.insert(corner.slot(d)).second) sum += corner[d];
        });
        EXPECT_NEAR(sim->vertex_mass()[v], sum, 1e-15);
      });
    };
    check();
    std::size_t vertices = sim->map().count_cells(Orbit{1, 2});
    for (int s = 0; s < 300 && sim->tears() < 20; ++s) {
      sim->step();
      if (sim->tears_last_step() > 0) check();
    }
    EXPECT_GT(sim->tears(), 0u);
    EXPECT_GT(sim->map().count_cells(Orbit{1, 2}), vertices);
    check();
  }
}

}  // namespace
}  // namespace rift::physics_test
