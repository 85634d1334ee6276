#include "rift/sim/simulation.hpp"

#include <gtest/gtest.h>

#include <random>

#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "test_spring_model.hpp"

namespace rift {
namespace {

Simulation make_cloth(IntegratorKind kind, Vec3 gravity, Real damping, Real dt = 1e-3) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, 4, 4)), {kind, dt, gravity});
  sim.set_total_mass(0.1);
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(60.0, damping));
  return sim;
}

TEST(Simulation, FreeFallFollowsTheParabola) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 2, 2)),
                 {IntegratorKind::kRK4, 1e-2, Vec3(0, 0, -9.81)});
  sim.set_total_mass(1.0);
  sim.initialise();
  const Vec3 start = sim.position()[0];
  for (int s = 0; s < 100; ++s)
    sim.step();
  const Real t = sim.time();
  EXPECT_NEAR(t, 1.0, 1e-12);
  EXPECT_NEAR(sim.position()[0].z(), start.z() - 0.5 * 9.81 * t * t, 1e-10);
  EXPECT_NEAR(sim.position()[0].x(), start.x(), 1e-15);
}

TEST(Simulation, MomentumIsConservedWithoutExternalForces) {
  Simulation sim = make_cloth(IntegratorKind::kRK4, Vec3::Zero(), 0.1);
  sim.initialise();
  std::mt19937 rng(7);
  std::normal_distribution<Real> noise(0.0, 0.3);
  for (Vec3& v : sim.velocity().values())
    v = Vec3(noise(rng), noise(rng), noise(rng));
  const Vec3 p0 = sim.momentum();
  for (int s = 0; s < 500; ++s)
    sim.step();
  EXPECT_LT((sim.momentum() - p0).norm(), 1e-12 * (1 + p0.norm()));
  EXPECT_GT(sim.kinetic_energy(), 0);
}

TEST(Simulation, PinnedVerticesStayPutAndDampingDissipates) {
  Simulation sim = make_cloth(IntegratorKind::kRK4, Vec3(0, 0, -9.81), 0.5);
  const std::size_t pinned = sim.pin_where([](const Vec3& p) { return p.y() > 0.99; });
  EXPECT_EQ(pinned, 5u);
  sim.initialise();
  std::vector<std::pair<Dart, Vec3>> top;
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    if (sim.position()[d].y() > 0.99) top.emplace_back(d, sim.position()[d]);
  });
  Real peak = 0;
  for (int s = 0; s < 3000; ++s) {
    sim.step();
    peak = std::max(peak, sim.kinetic_energy());
  }
  for (const auto& [d, p] : top)
    EXPECT_EQ(sim.position()[d], p);
  EXPECT_GT(peak, 0);
  EXPECT_LT(sim.kinetic_energy(), 0.2 * peak);  // the swing is dying out
  EXPECT_NEAR(sim.total_mass(), 0.1, 1e-12);
}

TEST(Simulation, UndampedSpringsConserveEnergyWithRk4) {
  // Vertex masses of 4 g on 60 N/m springs: w ~ 120 rad/s, so w dt = 0.012
  // keeps RK4's own dissipation far below the tolerance.
  Simulation sim = make_cloth(IntegratorKind::kRK4, Vec3::Zero(), 0.0, 1e-4);
  sim.initialise();
  // Stretch the cloth by 10% and let it oscillate.
  for (Vec3& x : sim.position().values())
    x *= 1.1;
  const Real e0 = sim.kinetic_energy() + sim.potential_energy();
  ASSERT_GT(e0, 0);
  for (int s = 0; s < 2000; ++s)
    sim.step();
  const Real e1 = sim.kinetic_energy() + sim.potential_energy();
  EXPECT_NEAR(e1, e0, 1e-6 * e0);
}

TEST(Simulation, ALoopHoldsOnlyThePerVertexArraysItsScenesIntegratorNeeds) {
  // Counted by hand (docs/architecture.md, "The step's arrays"): every
  // explicit loop holds the forces (the stage buffer between steps), the
  // start forces and the inverse masses; RK4 adds its four stage arrays
  // (next stage x and v, two running sums); no acceleration array, no copy
  // of the positions without loads or handles.
  for (IntegratorKind kind : {IntegratorKind::kRK4, IntegratorKind::kSymplecticEuler}) {
    Simulation sim = make_cloth(kind, Vec3(0, 0, -9.81), 0.1);
    sim.initialise();
    for (int s = 0; s < 3; ++s)
      sim.step();
    const std::size_t n = sim.position().values().size();
    ASSERT_EQ(n, 25u);
    const std::size_t vec3_arrays = kind == IntegratorKind::kRK4 ? 6 : 2;
    EXPECT_EQ(sim.per_vertex_bytes(), n * (vec3_arrays * sizeof(Vec3) + sizeof(Real)))
        << to_string(kind);
  }
}

// The cloth of make_cloth with its top row (y = 1) on one handle moving at
// `velocity`.
Simulation make_cloth_on_a_handle(const Vec3& velocity) {
  Simulation sim = make_cloth(IntegratorKind::kRK4, Vec3(0, 0, -9.81), 0.1);
  auto handles = std::make_unique<Handles>(sim.map());
  HandleMotion motion;
  motion.velocity = velocity;
  const int h = handles->add(motion);
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    if (sim.position()[d].y() > 0.99) handles->hold(d, h, sim.position()[d]);
  });
  sim.set_handles(std::move(handles));
  sim.initialise();
  return sim;
}

TEST(Simulation, AHandlesWorkIsItsReactionAlongItsMotion) {
  // Every held vertex moves by velocity · dt in a step, so the work of the
  // handle in a step is its reaction at the step's start (what
  // handle_reactions() reports) along velocity · dt. The loop sums it over
  // the held vertices alone; a sum over every slot gives the same.
  const Vec3 velocity(0.2, 0, 0.1);
  Simulation sim = make_cloth_on_a_handle(velocity);
  ASSERT_EQ(sim.handles()->held_slots(sim.position().attachment()).size(), 5u);
  Real expected = 0;
  for (int s = 0; s < 200; ++s) {
    sim.step();
    ASSERT_EQ(sim.handle_reactions().size(), 1u);
    expected += sim.handle_reactions()[0].dot(velocity * sim.settings().dt);
  }
  EXPECT_GT(std::abs(expected), 1e-6);
  EXPECT_NEAR(sim.external_work(), expected, 1e-9 * std::abs(expected));
  // The loop keeps the held vertices' start positions, not every vertex's.
  const std::size_t n = sim.position().values().size();
  EXPECT_EQ(sim.per_vertex_bytes(), n * (6 * sizeof(Vec3) + sizeof(Real)) + 5 * sizeof(Vec3));
}

TEST(Simulation, RejectsNonPositiveSettings) {
  EXPECT_THROW(Simulation(assemble_gmap(make_grid(GridKind::Quad, 1, 1)),
                          {IntegratorKind::kRK4, 0.0, Vec3::Zero()}),
               std::invalid_argument);
  Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 1, 1)), {});
  EXPECT_THROW(sim.set_total_mass(-1), std::invalid_argument);
  EXPECT_THROW(sim.set_density(0), std::invalid_argument);
}

}  // namespace
}  // namespace rift
