// Force passes in lanes (rift/core/lanes.hpp, riftc's evaluate_lanes): a
// pass that stores nothing evaluates kWidth consecutive matches at once, a
// pass that stores runs the scalar body one match at a time. Both must give
// the same forces to the bit, whatever the state: a spring of zero length
// (the `if l > 0` branch that each lane picks for itself), matches left over
// past the last full set of lanes, grouped passes (counts) and plain ones,
// 2D and 3D packs, and after a tear reshuffled the matches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "physics_setup.hpp"
#include "rift/core/lanes.hpp"
#include "rift/io/load_map.hpp"
#include "same_bits.hpp"

namespace rift::physics_test {
namespace {

// Both passes of every interaction, into separate arrays; true when every
// coordinate has the same bits. `what` names the first difference.
bool lanes_match_scalar(Simulation& sim, std::string& what) {
  const ForceInput in{sim.position().values().data(), sim.velocity().values().data()};
  const std::size_t n = sim.position().values().size();
  for (const auto& model : sim.force_models()) {
    std::vector<Vec3> in_lanes(n, Vec3::Zero()), scalar(n, Vec3::Zero());
    model->add_forces(in, in_lanes.data(), false);
    model->add_forces(in, scalar.data(), true);
    for (std::size_t s = 0; s < n; ++s) {
      for (int i = 0; i < 3; ++i) {
        if (!test::same_bits(in_lanes[s][i], scalar[s][i])) {
          what = model->name() + ", vertex slot " + std::to_string(s) + ", coordinate " +
                 std::to_string(i) + ": " + std::to_string(in_lanes[s][i]) + " in lanes, " +
                 std::to_string(scalar[s][i]) + " alone";
          return false;
        }
      }
    }
  }
  return true;
}

// Positions rounded to a coarse lattice: many vertices land on their
// neighbours, so that many springs have length 0 in some lanes only.
void collapse(Simulation& sim, Real step) {
  move_vertices(sim, [step](const Vec3& p) {
    return Vec3(step * std::round(p.x() / step), step * std::round(p.y() / step),
                step * std::round(p.z() / step));
  });
}

struct Body {
  const char* mesh;
  std::vector<Use> interactions;
};

std::vector<Body> bodies() {
  // Sizes whose match counts are not multiples of the width: the last
  // matches go through the scalar loop after the lanes.
  return {{"grid:quad:7x5", paper_cloth_springs()},
          {"grid:tri:6x5", paper_cloth_springs()},
          {"grid:quad:3x3", paper_cloth_springs(0.0)},
          {"block:hex:3x2x2",
           {{"stretch", {{"stiffness", 200.0}, {"damping", 0.1}}},
            {"shear", {{"stiffness", 100.0}, {"damping", 0.1}}},
            {"volume_shear", {{"stiffness", 100.0}, {"damping", 0.1}}}}}};
}

TEST(Lanes, ForcesInLanesAreTheScalarForcesToTheBit) {
  for (const Body& body : bodies()) {
    for (const bool grouped : {true, false}) {
      SimSetup setup;
      setup.settings.group_interactions = grouped;
      setup.interactions = body.interactions;
      auto sim = simulate(load_map(body.mesh), setup);
      for (unsigned seed = 1; seed <= 4; ++seed) {
        deform(*sim, seed, 0.3);
        std::string what;
        EXPECT_TRUE(lanes_match_scalar(*sim, what))
            << body.mesh << (grouped ? " grouped" : " plain") << ", seed " << seed << ": " << what;
      }
    }
  }
}

TEST(Lanes, ZeroLengthSpringsInSomeLanesOnly) {
  for (const Body& body : bodies()) {
    SimSetup setup;
    setup.interactions = body.interactions;
    auto sim = simulate(load_map(body.mesh), setup);
    deform(*sim, 7, 0.2);
    collapse(*sim, 0.5);
    // The premise: vertices on top of one another, hence springs of length 0
    // next to springs that are not.
    std::vector<Vec3> points = sim->position().values();
    std::sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    const auto distinct = std::unique(points.begin(), points.end()) - points.begin();
    ASSERT_LT(distinct, static_cast<std::ptrdiff_t>(points.size())) << body.mesh;
    ASSERT_GT(distinct, 1) << body.mesh;
    const std::vector<Vec3> f = internal_forces(*sim);
    std::string what;
    EXPECT_TRUE(lanes_match_scalar(*sim, what)) << body.mesh << ": " << what;
    bool finite = true;
    for (const Vec3& x : f)
      finite = finite && x.allFinite();
    EXPECT_TRUE(finite) << body.mesh << ": a zero-length spring gave a non-finite force";
  }
}

TEST(Lanes, AfterTearsReshuffledTheMatches) {
  SimSetup setup;
  setup.interactions = paper_cloth_springs();
  setup.criteria = {{"spring_split", {{"threshold", 1e-9}}}};
  auto sim = simulate(load_map("grid:quad:9x7"), setup);
  deform(*sim, 3, 0.1);
  std::vector<Vec3> f = internal_forces(*sim);
  const ForceInput in{sim->position().values().data(), sim->velocity().values().data()};
  for (const auto& m : sim->force_models())
    m->add_forces(in, f.data(), true);  // the stored forces the criterion reads
  std::vector<TearCandidate> candidates;
  sim->criteria()[0]->collect(sim->map(), candidates);
  ASSERT_GT(candidates.size(), 10u);
  std::vector<Dart> touched;
  int tears = 0;
  for (std::size_t k = 0; k < candidates.size() && tears < 10; k += 7) {
    if (tear_at(*sim, candidates[k], touched)) ++tears;
  }
  ASSERT_GT(tears, 0);
  for (unsigned seed = 11; seed <= 13; ++seed) {
    deform(*sim, seed, 0.1);
    std::string what;
    EXPECT_TRUE(lanes_match_scalar(*sim, what)) << "seed " << seed << ": " << what;
  }
}

TEST(Lanes, WidthFollowsTheTarget) {
#if defined(__AVX__)
  EXPECT_EQ(lanes::kWidth, 4);
#else
  EXPECT_EQ(lanes::kWidth, 2);
#endif
  EXPECT_EQ(sizeof(lanes::Real), lanes::kWidth * sizeof(double));
}

}  // namespace
}  // namespace rift::physics_test
