// The divergence check (rift/sim/divergence.hpp): an unstable explicit step
// stops at the first step whose kinetic energy passes the scene's bound,
// with the step, vertex and fix named; legitimate motions that gain energy
// (free fall, released elastic energy, a thrown body) never trip it.
#include "rift/sim/divergence.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "rift/core/parallel.hpp"
#include "rift/core/state_embeddings.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/sim/simulation.hpp"
#include "test_spring_model.hpp"

namespace rift {
namespace {

Simulation springs(IntegratorKind kind, Real dt, Real stiffness, Vec3 gravity, int n = 6,
                   Real damping = 0) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, n, n)), {kind, dt, gravity});
  sim.set_total_mass(0.1);
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(stiffness, damping));
  return sim;
}

/// Whether a failure's message names the vertex of position slot s: as
/// "vertex N", N the mesh's own point number (the map keeps it), or as
/// "vertex slot s", followed by " of element" or the end of the clause.
bool names_vertex(const std::string& message, const Simulation& sim, Slot s) {
  const auto point = sim.map().embedding<std::int64_t>(std::string(state::kPointIndex));
  std::string name = "vertex slot " + std::to_string(s);
  for (std::size_t k = 0; k < sim.map().capacity(); ++k) {
    const auto d = static_cast<Dart>(k);
    if (point && sim.map().is_alive(d) && sim.position().slot(d) == s) {
      name = "vertex " + std::to_string(point[d]);
      break;
    }
  }
  return message.find(name + " ") != std::string::npos ||
         message.find(name + ";") != std::string::npos;
}

TEST(Divergence, UnstableEulerStopsAtTheFirstStepPastTheBound) {
  // A stretched, undamped, stiff mesh under explicit Euler gains energy by
  // a constant factor per step.
  Simulation sim = springs(IntegratorKind::kExplicitEuler, 2e-3, 2000, Vec3::Zero());
  sim.initialise();
  for (Vec3& x : sim.position().values())
    x *= 1.05;
  std::vector<Real> energies;
  std::string message;
  try {
    for (int s = 0; s < 10000; ++s) {
      sim.step();
      energies.push_back(sim.kinetic_energy());
    }
  } catch (const SimulationError& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "never stopped";
  const Real bound = sim.divergence().energy_bound(sim);
  EXPECT_GT(bound, 0);
  EXPECT_GT(sim.kinetic_energy(), bound) << message;
  // Every step before the one that stopped was under the (growing) bound.
  EXPECT_EQ(energies.size() + 1, sim.steps_done());
  for (Real e : energies)
    EXPECT_LE(e, bound);
  EXPECT_NE(message.find("diverged at step " + std::to_string(sim.steps_done())), std::string::npos)
      << message;
  EXPECT_NE(message.find("kinetic energy"), std::string::npos) << message;
  EXPECT_NE(message.find("vertex"), std::string::npos) << message;
  EXPECT_NE(message.find("dt = 0.0005"), std::string::npos) << message;
  // Long before the numbers overflow.
  EXPECT_LT(sim.kinetic_energy(), 1e6 * bound);
}

TEST(Divergence, LegitimateMotionsNeverTripIt) {
  // Free fall for 10 s: kinetic energy grows as t^2, the bound with it.
  {
    Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 2, 2)),
                   {IntegratorKind::kRK4, 1e-2, Vec3(0, 0, -9.81)});
    sim.set_total_mass(1.0);
    for (int s = 0; s < 1000; ++s)
      ASSERT_NO_THROW(sim.step()) << s;
  }
  // A stretched mesh released with RK4 (stable dt): elastic energy turns
  // into motion, the total stays that of the start.
  {
    Simulation sim = springs(IntegratorKind::kRK4, 1e-3, 60, Vec3::Zero());
    sim.initialise();
    for (Vec3& x : sim.position().values())
      x *= 1.3;
    for (int s = 0; s < 2000; ++s)
      ASSERT_NO_THROW(sim.step()) << s;
  }
  // A body thrown upwards fast, under gravity, with springs.
  {
    Simulation sim = springs(IntegratorKind::kSymplecticEuler, 1e-3, 60, Vec3(0, 0, -9.81));
    sim.initialise();
    for (Vec3& v : sim.velocity().values())
      v = Vec3(3, 0, 40);
    for (int s = 0; s < 3000; ++s)
      ASSERT_NO_THROW(sim.step()) << s;
  }
}

TEST(Divergence, NonFiniteStateNamesTheVertex) {
  Simulation sim = springs(IntegratorKind::kRK4, 1e-3, 60, Vec3(0, 0, -9.81));
  sim.step();
  sim.velocity().values()[3] = Vec3(0, std::nan(""), 0);
  try {
    sim.step();
    FAIL() << "a NaN velocity went through";
  } catch (const SimulationError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("exploded at step 2"), std::string::npos) << m;
    EXPECT_NE(m.find("non-finite"), std::string::npos) << m;
    // The step spread the NaN to slot 3's neighbours: the message names the
    // first non-finite vertex in slot order.
    Slot first = kNoSlot;
    for (Slot v = 0; v < sim.velocity().values().size() && first == kNoSlot; ++v) {
      if (!sim.velocity().values()[v].allFinite() || !sim.position().values()[v].allFinite())
        first = v;
    }
    ASSERT_NE(first, kNoSlot);
    EXPECT_TRUE(names_vertex(m, sim, first)) << m;
  }
  // An infinite position is caught as well.
  Simulation again = springs(IntegratorKind::kSymplecticEuler, 1e-3, 60, Vec3(0, 0, -9.81));
  again.step();
  const Slot last = static_cast<Slot>(again.position().values().size() - 1);
  again.position().values()[last].x() = std::numeric_limits<Real>::infinity();
  try {
    again.step();
    FAIL() << "an infinite position went through";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
  }
}

TEST(Divergence, WithoutAnEnergyScaleTheSpeedCheckStillHolds) {
  // At rest, no gravity, no strain: the energy scale is 0 and only the speed
  // check (a vertex crossing the whole body in one step) can trip.
  Simulation sim = springs(IntegratorKind::kRK4, 1e-3, 0, Vec3::Zero());
  sim.step();
  EXPECT_EQ(sim.divergence().energy_bound(sim), 0);
  const Real across = sim.divergence().length_scale();
  ASSERT_GT(across, 0);
  sim.velocity().values()[5] = Vec3(0.5 * across / 1e-3, 0, 0);  // half the body per step
  EXPECT_NO_THROW(sim.step());
  sim.velocity().values()[5] = Vec3(3 * across / 1e-3, 0, 0);
  try {
    sim.step();
    FAIL() << "a vertex crossed the body three times in one step";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("farther than the whole body"), std::string::npos)
        << e.what();
    EXPECT_TRUE(names_vertex(e.what(), sim, 5)) << e.what();
  }
}

TEST(Divergence, ManyBlocksNameTheFirstVertexInSlotOrderOnAnyThreads) {
  // The check runs in parallel blocks of kParallelBlock vertices; combined in
  // block order, it names the vertex the serial pass named (the first in slot
  // order) whatever the thread count.
  for (const int threads : {1, 2, 8}) {
    set_thread_count(threads);
    Simulation sim = springs(IntegratorKind::kRK4, 1e-3, 0, Vec3::Zero(), 99);
    sim.step();
    const std::size_t n = sim.velocity().values().size();
    ASSERT_GT(n, 8 * kParallelBlock) << "too few blocks to spread";
    const Real across = sim.divergence().length_scale();
    // Two vertices as fast, in different blocks: the lower slot is named.
    const auto first = static_cast<Slot>(3 * kParallelBlock + 17);
    const auto later = static_cast<Slot>(7 * kParallelBlock + 5);
    sim.velocity().values()[later] = Vec3(0, 3 * across / 1e-3, 0);
    sim.velocity().values()[first] = Vec3(0, 3 * across / 1e-3, 0);
    try {
      sim.step();
      FAIL() << threads << " threads: two vertices crossed the body in one step";
    } catch (const SimulationError& e) {
      EXPECT_TRUE(names_vertex(e.what(), sim, first)) << threads << " threads: " << e.what();
    }
    // Non-finite velocities in two blocks: the first in slot order is named.
    Simulation broken = springs(IntegratorKind::kRK4, 1e-3, 0, Vec3::Zero(), 99);
    broken.step();
    broken.velocity().values()[later] = Vec3(std::nan(""), 0, 0);
    broken.velocity().values()[first + kParallelBlock] = Vec3(std::nan(""), 0, 0);
    try {
      broken.step();
      FAIL() << threads << " threads: a NaN velocity went through";
    } catch (const SimulationError& e) {
      Slot bad = kNoSlot;
      const auto& v = broken.velocity().values();
      const auto& x = broken.position().values();
      for (Slot s = 0; s < v.size() && bad == kNoSlot; ++s) {
        if (!v[s].allFinite() || !x[s].allFinite()) bad = s;
      }
      ASSERT_NE(bad, kNoSlot);
      EXPECT_TRUE(names_vertex(e.what(), broken, bad)) << threads << " threads: " << e.what();
    }
  }
  set_thread_count(0);
}

TEST(Divergence, FactorZeroKeepsOnlyTheFiniteCheck) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, 6, 6)),
                 {IntegratorKind::kExplicitEuler, 2e-3, Vec3::Zero(), 0, false, 0.0});
  sim.set_total_mass(0.1);
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(2000, 0));
  sim.initialise();
  for (Vec3& x : sim.position().values())
    x *= 1.05;
  // Grows far past any bound without stopping, until the numbers overflow.
  bool stopped = false;
  for (int s = 0; s < 100000 && !stopped; ++s) {
    try {
      sim.step();
    } catch (const SimulationError& e) {
      stopped = true;
      EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(stopped);
}

}  // namespace
}  // namespace rift
