// Growth headroom under tears (rift/core/huge_pages.hpp, issue 12: a tear
// costs what it touches). The dart arrays, slot arrays, columns, match
// caches and inverse masses of a map have room to grow in place: tears that
// stay within it move none of them (no copy of the whole map), and a map
// that outgrows its headroom stays valid and gives, bit for bit, what a map
// that never had to grow gives.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "physics_setup.hpp"
#include "rift/core/huge_pages.hpp"

namespace rift::physics_test {
namespace {

using Stretch2d = packs::mass_spring2d::StretchInteraction;

/// Restores the default factor when a test ends, even a failed one.
struct FactorGuard {
  std::size_t saved = headroom_factor();
  std::size_t saved_min = headroom_min_bytes();
  ~FactorGuard() { set_headroom_factor(saved, saved_min); }
};

/// A 10x10 paper cloth stretched by 30 %: spring_split tears it at every
/// step (a few tears a step).
std::unique_ptr<Simulation> tearing_cloth() {
  SimSetup setup;
  setup.interactions = paper_cloth_springs();
  setup.criteria = {{"spring_split", {{"threshold", 0.5}}}};
  setup.settings.max_tears_per_step = 3;
  setup.settings.dt = 1e-4;
  auto sim = simulate(assemble_gmap(make_grid(GridKind::Quad, 10, 10)), setup);
  move_vertices(*sim, [](const Vec3& x) { return Vec3(1.3 * x.x(), 1.3 * x.y(), x.z()); });
  return sim;
}

const Stretch2d& stretch(const Simulation& sim) {
  for (const auto& model : sim.force_models()) {
    if (const auto* s = dynamic_cast<const Stretch2d*>(model.get())) return *s;
  }
  throw std::logic_error("no stretch interaction");
}

/// Where the arrays a tear appends to live.
struct Buffers {
  std::vector<const void*> data;

  explicit Buffers(const Simulation& sim) {
    for (int i = 0; i <= sim.map().dimension(); ++i)
      data.push_back(sim.map().alpha_data(i));
    data.push_back(sim.position().attachment().slot_data());
    data.push_back(sim.position().values().data());
    data.push_back(sim.velocity().values().data());
    data.push_back(sim.vertex_mass().values().data());
    data.push_back(sim.inverse_masses().data());
    data.push_back(stretch(sim).cache().matches().data());
  }
  bool operator==(const Buffers&) const = default;
};

TEST(Headroom, TearsWithinTheHeadroomCopyNoArrayOfTheMap) {
  const FactorGuard guard;
  set_headroom_factor(2, 0);  // a 10x10 cloth's arrays are small
  auto sim = tearing_cloth();
  const std::size_t darts = sim->map().capacity();
  const std::size_t slots = sim->position().attachment().slot_capacity();
  const Buffers before(*sim);
  // Tear until the map has grown, without passing twice its first size.
  int steps = 0;
  while (sim->position().attachment().slot_capacity() < slots + 8 && steps < 40) {
    sim->step();
    ++steps;
  }
  ASSERT_GT(sim->position().attachment().slot_capacity(), slots) << "nothing tore";
  // A split unsews: no dart is added, but vertex slots and matches are.
  ASSERT_LT(sim->map().capacity(), 2 * darts);
  ASSERT_LT(sim->position().attachment().slot_capacity(), 2 * slots);
  EXPECT_TRUE(Buffers(*sim) == before)
      << "a tear moved an array of the map after " << steps << " steps";
  EXPECT_TRUE(sim->map().is_valid());
}

/// Positions and velocities after `steps` tearing steps, as bytes, with every
/// array given `factor` times the room it asks for.
struct Outcome {
  std::vector<Vec3> x, v;
  std::size_t darts = 0, vertices = 0;
  bool moved = false;  ///< whether the dart arrays had to move
};

Outcome tear(std::size_t factor, int steps) {
  set_headroom_factor(factor, 0);
  auto sim = tearing_cloth();
  const Buffers before(*sim);
  for (int k = 0; k < steps; ++k) {
    sim->step();
    EXPECT_TRUE(sim->map().is_valid()) << "factor " << factor << ", step " << k;
  }
  Outcome o;
  o.x = sim->position().values();
  o.v = sim->velocity().values();
  o.darts = sim->map().size();
  o.vertices = sim->map().count_cells(Orbit{1, 2});
  o.moved = !(Buffers(*sim) == before);
  return o;
}

bool same_bytes(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

TEST(Headroom, AMapThatOutgrowsItsHeadroomGivesTheSameBits) {
  const FactorGuard guard;
  // Exact buffers: the first tear already outgrows them.
  const Outcome exact = tear(1, 30);
  // Room for sixteen times the map: nothing moves.
  const Outcome roomy = tear(16, 30);
  EXPECT_TRUE(exact.moved);
  EXPECT_FALSE(roomy.moved);
  EXPECT_GT(roomy.vertices, 121u) << "nothing tore";
  EXPECT_EQ(exact.darts, roomy.darts);
  EXPECT_EQ(exact.vertices, roomy.vertices);
  EXPECT_TRUE(same_bytes(exact.x, roomy.x));
  EXPECT_TRUE(same_bytes(exact.v, roomy.v));
}

}  // namespace
}  // namespace rift::physics_test
