// Ctrl-C inside a step (rift/core/interrupt.hpp): the flag is polled inside
// the force pass, so a step stops within one block of matches, not at its
// end; the map stays usable (no mark or scratch buffer is leaked).
#include "rift/core/interrupt.hpp"

#include <gtest/gtest.h>

#include <csignal>

#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/sim/cached_interaction.hpp"
#include "rift/sim/simulation.hpp"

namespace rift {
namespace {

// One match per dart; the interrupt "arrives" (as from a signal handler)
// when the pass reaches match `interrupt_at`.
struct CountingKernel {
  struct Match {
    Slot vertex;
  };
  static constexpr Orbit kSupport = Orbit{};
  static constexpr int kRadius = 0;

  const std::string& name() const { return name_; }
  void initialise(GMap& map) { position = map.embedding<Vec3>("position"); }
  bool match(const GMap&, Dart d, Match& m) const {
    m.vertex = position.slot(d);
    return true;
  }
  void add_forces(const Match& m, const ForceInput& in, Vec3* f, bool) {
    if (++calls == interrupt_at) request_interrupt();
    f[m.vertex] += 1e-9 * in.x[m.vertex];
  }
  void reset_stored(const Match&) {}
  Real energy(const Match&, const ForceInput&) const { return 0; }

  std::string name_ = "counting";
  Embedding<Vec3> position;
  std::size_t calls = 0, interrupt_at = 0;
};

class Interrupt : public ::testing::Test {
 protected:
  void TearDown() override { clear_interrupt(); }
};

TEST_F(Interrupt, AForcePassStopsWithinOneBlockOfMatches) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 80, 80)),
                 {IntegratorKind::kRK4, 1e-3, Vec3(0, 0, -9.81)});
  sim.set_total_mass(1.0);
  auto model = std::make_unique<CachedInteraction<CountingKernel>>();
  CountingKernel& kernel = model->kernel();
  sim.add_force_model(std::move(model));
  sim.initialise();
  const std::size_t matches = sim.force_models()[0]->active_matches();
  ASSERT_GT(matches, 5u * 4096u);
  sim.step();
  const std::vector<Vec3> before = sim.position().values();
  kernel.calls = 0;
  kernel.interrupt_at = 5000;  // in the second block of the first stage
  EXPECT_THROW(sim.step(), Interrupted);
  EXPECT_GE(kernel.calls, 5000u);
  EXPECT_LE(kernel.calls, 5000u + 4096u) << "the pass ran on after the interrupt";
  EXPECT_EQ(sim.steps_done(), 1u);
  EXPECT_EQ(sim.position().values(), before);  // no half-integrated positions
  EXPECT_EQ(sim.map().reserved_marks(), 0);
  EXPECT_TRUE(sim.map().is_valid());
}

TEST_F(Interrupt, APendingRequestStopsTheNextStepAtOnce) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 4, 4)),
                 {IntegratorKind::kRK4, 1e-3, Vec3(0, 0, -9.81)});
  sim.set_total_mass(1.0);
  sim.step();
  request_interrupt();
  EXPECT_THROW(sim.step(), Interrupted);
  EXPECT_EQ(sim.steps_done(), 1u);
  clear_interrupt();
  EXPECT_NO_THROW(sim.step());
  EXPECT_EQ(sim.steps_done(), 2u);
}

TEST_F(Interrupt, SigintRaisesTheFlagWhileAHandlerIsInstalled) {
  {
    InterruptHandler handler;
    EXPECT_FALSE(interrupt_requested());
    std::raise(SIGINT);  // would end the test program without the handler
    EXPECT_TRUE(interrupt_requested());
  }
  clear_interrupt();
  InterruptHandler again;  // a new run starts with the flag cleared
  EXPECT_FALSE(interrupt_requested());
}

TEST_F(Interrupt, ATraversalThatThrowsReleasesItsMark) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 10, 10));
  request_interrupt();
  EXPECT_THROW(map.for_each_cell(Orbit::cell(0, 2), [](Dart) { throw_if_interrupted(); }),
               Interrupted);
  EXPECT_THROW(map.for_each_in_orbit(0, Orbit{0, 1, 2}, [](Dart) { throw_if_interrupted(); }),
               Interrupted);
  EXPECT_EQ(map.reserved_marks(), 0);
  clear_interrupt();
  std::size_t vertices = 0;
  map.for_each_cell(Orbit::cell(0, 2), [&](Dart) { ++vertices; });
  EXPECT_EQ(vertices, 121u);
  EXPECT_EQ(map.orbit_size(0, Orbit{0, 1, 2}), 100u * 8u);
}

}  // namespace
}  // namespace rift
