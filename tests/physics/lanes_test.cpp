// Force passes in lanes (rift/core/lanes.hpp, riftc's evaluate_lanes): a
// pass over consecutive matches evaluates kWidth of them at once, and
// SimulationSettings::lanes = false evaluates each alone. Both must give the
// same forces and stored forces to the bit, whatever the state: a spring of
// zero length (the `if l > 0` branch that each lane picks for itself),
// matches left over past the last full set of lanes, grouped passes (counts,
// terms) and plain ones, 2D and 3D packs, and after tears reshuffled the
// matches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "lanes_constructs.hpp"
#include "physics_setup.hpp"
#include "rift/core/lanes.hpp"
#include "rift/io/load_map.hpp"
#include "same_bits.hpp"

namespace rift::physics_test {
namespace {

// Every interaction's force pass, without and with stores, in a simulation
// with lanes and one without, on the same state: true when every coordinate
// of the forces and of the stored forces has the same bits. `what` names
// the first difference.
bool lanes_match_scalar(Simulation& lanes, Simulation& scalar, std::string& what) {
  const std::size_t n = lanes.position().values().size();
  if (scalar.position().values().size() != n ||
      lanes.force_models().size() != scalar.force_models().size()) {
    what = "the two simulations differ";
    return false;
  }
  auto same = [&](const std::vector<Vec3>& a, const std::vector<Vec3>& b, const std::string& of) {
    for (std::size_t s = 0; s < a.size(); ++s) {
      for (int i = 0; i < 3; ++i) {
        if (!test::same_bits(a[s][i], b[s][i])) {
          what = of + ", slot " + std::to_string(s) + ", coordinate " + std::to_string(i) + ": " +
                 std::to_string(a[s][i]) + " in lanes, " + std::to_string(b[s][i]) + " alone";
          return false;
        }
      }
    }
    return true;
  };
  for (const bool store : {false, true}) {
    for (std::size_t k = 0; k < lanes.force_models().size(); ++k) {
      std::vector<Vec3> f_lanes(n, Vec3::Zero()), f_scalar(n, Vec3::Zero());
      lanes.force_models()[k]->add_forces(
          {lanes.position().values().data(), lanes.velocity().values().data()}, f_lanes.data(),
          store);
      scalar.force_models()[k]->add_forces(
          {scalar.position().values().data(), scalar.velocity().values().data()}, f_scalar.data(),
          store);
      const std::string name = lanes.force_models()[k]->name();
      if (!same(f_lanes, f_scalar, name + (store ? " (storing pass)" : ""))) return false;
    }
  }
  for (const char* stored : {"f_stretch", "f_shear", "f_volume_shear", "f_all"}) {
    const auto a = lanes.map().embedding<Vec3>(stored);
    const auto b = scalar.map().embedding<Vec3>(stored);
    if (!a || !b || a.values().empty()) continue;
    if (!same(a.values(), b.values(), std::string("stored ") + stored)) return false;
  }
  return true;
}

// A simulation of `mesh` with lanes on or off, the rest alike.
std::unique_ptr<Simulation> make(const char* mesh, const std::vector<Use>& interactions, bool lanes,
                                 bool grouped = true, const std::vector<Use>& criteria = {}) {
  SimSetup setup;
  setup.settings.lanes = lanes;
  setup.settings.group_interactions = grouped;
  setup.interactions = interactions;
  setup.criteria = criteria;
  return simulate(load_map(mesh), setup);
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
      auto lanes = make(body.mesh, body.interactions, true, grouped);
      auto scalar = make(body.mesh, body.interactions, false, grouped);
      for (unsigned seed = 1; seed <= 4; ++seed) {
        deform(*lanes, seed, 0.3);
        deform(*scalar, seed, 0.3);
        std::string what;
        EXPECT_TRUE(lanes_match_scalar(*lanes, *scalar, what))
            << body.mesh << (grouped ? " grouped" : " plain") << ", seed " << seed << ": " << what;
      }
    }
  }
}

TEST(Lanes, ZeroLengthSpringsInSomeLanesOnly) {
  for (const Body& body : bodies()) {
    auto lanes = make(body.mesh, body.interactions, true);
    auto scalar = make(body.mesh, body.interactions, false);
    for (Simulation* sim : {lanes.get(), scalar.get()}) {
      deform(*sim, 7, 0.2);
      collapse(*sim, 0.5);
    }
    // The premise: vertices on top of one another, hence springs of length 0
    // next to springs that are not.
    std::vector<Vec3> points = lanes->position().values();
    std::sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    const auto distinct = std::unique(points.begin(), points.end()) - points.begin();
    ASSERT_LT(distinct, static_cast<std::ptrdiff_t>(points.size())) << body.mesh;
    ASSERT_GT(distinct, 1) << body.mesh;
    std::string what;
    EXPECT_TRUE(lanes_match_scalar(*lanes, *scalar, what)) << body.mesh << ": " << what;
    bool finite = true;
    for (const Vec3& x : internal_forces(*lanes))
      finite = finite && x.allFinite();
    EXPECT_TRUE(finite) << body.mesh << ": a zero-length spring gave a non-finite force";
  }
}

TEST(Lanes, AfterTearsReshuffledTheMatches) {
  const std::vector<Use> split = {{"spring_split", {{"threshold", 1e-9}}}};
  auto lanes = make("grid:quad:9x7", paper_cloth_springs(), true, true, split);
  auto scalar = make("grid:quad:9x7", paper_cloth_springs(), false, true, split);
  std::vector<TearCandidate> candidates;
  for (Simulation* sim : {lanes.get(), scalar.get()}) {
    deform(*sim, 3, 0.1);
    std::vector<Vec3> f(sim->position().values().size(), Vec3::Zero());
    const ForceInput in{sim->position().values().data(), sim->velocity().values().data()};
    for (const auto& m : sim->force_models())
      m->add_forces(in, f.data(), true);  // the stored forces the criterion reads
  }
  lanes->criteria()[0]->collect(lanes->map(), candidates);
  ASSERT_GT(candidates.size(), 10u);
  std::vector<Dart> touched;
  int tears = 0;
  for (std::size_t k = 0; k < candidates.size() && tears < 10; k += 7) {
    const bool torn = tear_at(*lanes, candidates[k], touched);
    ASSERT_EQ(torn, tear_at(*scalar, candidates[k], touched));
    if (torn) ++tears;
  }
  ASSERT_GT(tears, 0);
  for (unsigned seed = 11; seed <= 13; ++seed) {
    deform(*lanes, seed, 0.1);
    deform(*scalar, seed, 0.1);
    std::string what;
    EXPECT_TRUE(lanes_match_scalar(*lanes, *scalar, what)) << "seed " << seed << ": " << what;
  }
}

// tests/physics/lanes_constructs.rules: one interaction with every construct
// of the lanes form (when, if on reals and vec3s, and/or/not, comparisons,
// min/max/clamp/abs/sqrt, normalize/cross/dot, vec3(...), a coordinate,
// stop_gradient, a bool parameter, vec3 and real columns).
TEST(Lanes, EveryConstructOfTheLanesFormGivesTheScalarBits) {
  static const PackRegistry registry = [] {
    PackRegistry r;
    rift_register_pack_lanes_constructs(r);
    return r;
  }();
  auto make_constructs = [&](bool lanes) {
    SimSetup setup;
    setup.registry = &registry;
    setup.settings.lanes = lanes;
    setup.interactions = {{"every_construct", {{"stiffness", 50.0}, {"cap", 0.05}}}};
    return simulate(load_map("block:hex:3x2x2"), setup);
  };
  auto lanes = make_constructs(true);
  auto scalar = make_constructs(false);
  for (unsigned seed = 1; seed <= 6; ++seed) {
    for (Simulation* sim : {lanes.get(), scalar.get()}) {
      deform(*sim, seed, 0.3);
      if (seed % 2 == 0) collapse(*sim, 0.5);  // zero lengths, `same` true in some lanes
    }
    std::string what;
    EXPECT_TRUE(lanes_match_scalar(*lanes, *scalar, what)) << "seed " << seed << ": " << what;
    Real largest = 0;
    for (const Vec3& f : internal_forces(*lanes))
      largest = std::max(largest, f.norm());
    EXPECT_GT(largest, 0.1) << "seed " << seed;  // the law pulls: the comparison means something
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
