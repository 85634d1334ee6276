// The tearing part of the loop, driven by a hand-written criterion (the real
// criteria are compiled from rules/): candidates are applied in order, the
// map stays valid, the total mass is unchanged, and the cap is honoured.
#include <gtest/gtest.h>

#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/sim/simulation.hpp"
#include "test_spring_model.hpp"

namespace rift {
namespace {

// Separates the two faces of every inner edge longer than `limit`.
class LongEdgeCriterion final : public Criterion {
 public:
  explicit LongEdgeCriterion(Real limit) : limit_(limit) {}
  const std::string& name() const override { return name_; }
  void initialise(GMap& map) override { position_ = map.embedding<Vec3>("position"); }
  void collect(const GMap& map, std::vector<TearCandidate>& out) const override {
    map.for_each_cell(Orbit{0, 2}, [&](Dart d) {
      if (map.is_free(d, 2)) return;
      const Real len = (position_[map.alpha(d, 0)] - position_[d]).norm();
      if (len > limit_) out.push_back({0, d, len, {}, 0});
    });
  }
  bool apply(GMap& map, const TearCandidate& c, std::vector<Dart>& touched) override {
    if (map.is_free(c.at, 2)) return false;
    map.for_each_in_orbit(c.at, Orbit{0, 2}, [&](Dart x) { touched.push_back(x); });
    map.unsew(c.at, 2);
    ++applied;
    return true;
  }
  int applied = 0;

 private:
  std::string name_ = "long_edge";
  Real limit_;
  Embedding<Vec3> position_;
};

Simulation hanging_cloth(int cap, Real limit, LongEdgeCriterion** criterion) {
  SimulationSettings settings{IntegratorKind::kRK4, 1e-3, Vec3(0, -9.81, 0), cap, true};
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, 6, 6)), settings);
  sim.set_total_mass(0.1);
  sim.pin_where([](const Vec3& p) { return p.y() > 0.99 && (p.x() < 0.01 || p.x() > 0.99); });
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(5.0, 0.05));
  auto c = std::make_unique<LongEdgeCriterion>(limit);
  *criterion = c.get();
  sim.add_criterion(std::move(c));
  sim.initialise();
  return sim;
}

TEST(Tearing, SoftClothTearsStaysValidAndKeepsItsMass) {
  LongEdgeCriterion* criterion = nullptr;
  Simulation sim = hanging_cloth(0, 0.25, &criterion);
  const std::size_t vertices_before = sim.map().count_cells_of_dimension(0);
  for (int s = 0; s < 400; ++s) {
    sim.step();
    ASSERT_NEAR(sim.total_mass(), 0.1, 1e-12) << "step " << s;
  }
  EXPECT_GT(sim.tears(), 0u);
  EXPECT_EQ(static_cast<std::size_t>(criterion->applied), sim.tears());
  EXPECT_TRUE(sim.map().is_valid());
  EXPECT_GT(sim.map().count_cells_of_dimension(0), vertices_before);  // split vertices
}

TEST(Tearing, PerStepCapIsHonoured) {
  LongEdgeCriterion* criterion = nullptr;
  Simulation sim = hanging_cloth(1, 0.25, &criterion);
  for (int s = 0; s < 400; ++s) {
    sim.step();
    ASSERT_LE(sim.tears_last_step(), 1u);
  }
  EXPECT_GT(sim.tears(), 0u);
}

TEST(Tearing, StiffThresholdNeverTears) {
  LongEdgeCriterion* criterion = nullptr;
  Simulation sim = hanging_cloth(0, 10.0, &criterion);
  for (int s = 0; s < 200; ++s)
    sim.step();
  EXPECT_EQ(sim.tears(), 0u);
}

TEST(Explosion, NonFinitePositionsStopWithTheStep) {
  // Divergence factor 0: only the finite check (the energy check would stop
  // this at step 1, tests/sim/divergence_test.cpp).
  SimulationSettings settings{
      IntegratorKind::kExplicitEuler, 0.5, Vec3(0, -9.81, 0), 0, false, 0.0};
  Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 3, 3)), settings);
  sim.set_total_mass(0.001);
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(1e6, 0.0));
  sim.initialise();
  for (Vec3& x : sim.position().values())
    x *= 1.5;
  try {
    for (int s = 0; s < 10000; ++s)
      sim.step();
    FAIL() << "the simulation should have exploded";
  } catch (const SimulationError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("exploded at step"), std::string::npos) << msg;
    EXPECT_NE(msg.find("of element"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace rift
