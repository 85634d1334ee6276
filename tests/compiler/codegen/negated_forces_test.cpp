// Forces that negate another force of their interaction (`force b.f = -fa`,
// golden/ok_negated_forces/case.rules): riftc scatters them as a subtraction
// of the force they negate (and, over groups, of count times it). The pack's
// `shared` interaction negates shared nodes, `-(-fa)` included, where
// `written_out` spells every force out: both must give the same forces and
// the same stored forces, bit for bit, over matches and over groups.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "negated.hpp"
#include "rift/io/load_map.hpp"
#include "rift/sim/simulation.hpp"

namespace {

namespace np = rift::packs::negated;
using rift::ComponentUse;
using rift::GMap;
using rift::Real;
using rift::Simulation;
using rift::Vec3;

struct Forces {
  std::vector<Vec3> on_vertices;         // the pass's sums
  std::vector<Vec3> stored_f, stored_g;  // each half-edge's stored forces, by <> slot
  std::size_t evaluated = 0, matches = 0;
};

/// One storing force pass of `interaction` over a grid deformed and set
/// moving at random (the same for every call), grouped or match by match.
Forces one_pass(const char* interaction, bool grouped) {
  GMap g = rift::load_map("grid:mix:4x4");
  const np::Pack pack;
  pack.initialise(g);
  rift::SimulationSettings settings;
  settings.group_interactions = grouped;
  Simulation sim(std::move(g), settings);
  sim.set_total_mass(1.0);
  ComponentUse use;
  use.name = interaction;
  sim.add_force_model(pack.make_interaction(use));
  sim.initialise();
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (Vec3& x : sim.position().values())
    x += 0.1 * Vec3(u(rng), u(rng), u(rng));
  for (Vec3& v : sim.velocity().values())
    v = 0.5 * Vec3(u(rng), u(rng), u(rng));
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  Forces out;
  out.on_vertices.assign(x.size(), Vec3::Zero());
  rift::ForceModel& m = *sim.force_models()[0];
  m.clear_accumulated();
  m.add_forces({x.data(), v.data()}, out.on_vertices.data(), true);
  out.stored_f = sim.map().embedding<Vec3>("f").values();
  out.stored_g = sim.map().embedding<Vec3>("g").values();
  out.evaluated = m.evaluated_matches();
  out.matches = m.active_matches();
  return out;
}

void expect_same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(a[i][c], b[i][c]) << what << " at slot " << i << ", component " << c;
  }
}

TEST(NegatedForces, SubtractedForcesAreTheForcesSpelledOutBitForBit) {
  for (const bool grouped : {false, true}) {
    SCOPED_TRACE(grouped ? "over groups" : "match by match");
    const Forces shared = one_pass("shared", grouped);
    const Forces written = one_pass("written_out", grouped);
    // Grouped, interior edges' two half-edges are evaluated once.
    if (grouped) {
      EXPECT_LT(shared.evaluated, shared.matches);
    } else {
      EXPECT_EQ(shared.evaluated, shared.matches);
    }
    EXPECT_EQ(shared.evaluated, written.evaluated);
    expect_same_bits(shared.on_vertices, written.on_vertices, "vertex force");
    expect_same_bits(shared.stored_f, written.stored_f, "stored f");
    expect_same_bits(shared.stored_g, written.stored_g, "stored g");
    Real largest = 0;
    for (const Vec3& f : shared.stored_f)
      largest = std::max(largest, f.norm());
    EXPECT_GT(largest, 0.1);  // deformed and moving: the springs pull
    // a receives fa (f) and -(-fa) = fa (g), b receives -fa twice: the
    // vertices' sums are twice the springs' forces, not zero.
    Real strongest = 0;
    for (const Vec3& f : shared.on_vertices)
      strongest = std::max(strongest, f.norm());
    EXPECT_GT(strongest, 0.1);
  }
}

}  // namespace
