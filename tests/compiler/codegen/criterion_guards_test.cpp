// A criterion's guards change what collect() computes, never what it finds:
// golden/ok_criterion_guards/case.rules writes one measure three times, once
// with guards (a threshold > 0) and twice without (a threshold of any sign,
// and >= against a threshold >= 0, where a failed condition's 0 may pass).
// On cloths bent at random, with some faces turned off, the three must find
// the same edges with the same measures, to the bit.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "guards.hpp"
#include "rift/io/load_map.hpp"

namespace {

namespace pg = rift::packs::guards;
using rift::ComponentUse;
using rift::Dart;
using rift::GMap;
using rift::Real;
using rift::SceneParam;
using rift::TearCandidate;
using rift::Value;
using rift::Vec3;

/// A 6x6 quad grid moved at random in all three directions, so that the
/// far corners of some edges lie behind them, with the weight of about a
/// quarter of the faces below 0.5.
GMap bent_grid(std::mt19937& rng) {
  GMap g = rift::load_map("grid:quad:6x6");
  pg::Pack().initialise(g);
  auto x = g.embedding<Vec3>("position");
  auto weight = g.embedding<Real>("weight");
  std::uniform_real_distribution<Real> jitter(-0.12, 0.12);
  std::uniform_real_distribution<Real> unit(0.0, 1.0);
  g.for_each_cell(rift::Orbit{1, 2},
                  [&](Dart v) { x[v] += Vec3(jitter(rng), jitter(rng), 2.0 * jitter(rng)); });
  g.for_each_cell(rift::Orbit{0, 1}, [&](Dart f) { weight[f] = unit(rng) < 0.25 ? 0.0 : 1.0; });
  return g;
}

std::vector<TearCandidate> found(GMap& g, const char* criterion, Real threshold) {
  ComponentUse u;
  u.name = criterion;
  u.params["threshold"] = SceneParam{Value(threshold), 0};
  auto c = pg::Pack().make_criterion(u);
  c->initialise(g);
  std::vector<TearCandidate> out;
  c->collect(g, out);
  return out;
}

void expect_same(const std::vector<TearCandidate>& a, const std::vector<TearCandidate>& b,
                 const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].at, b[i].at) << what << ", candidate " << i;
    EXPECT_EQ(a[i].measure, b[i].measure) << what << ", candidate " << i;
  }
}

TEST(CriterionGuards, GuardedAndUnguardedFindTheSameCandidates) {
  const std::size_t interior_edges = 2 * 6 * 5;
  for (const unsigned seed : {1u, 2u, 3u, 4u}) {
    std::mt19937 rng(seed);
    GMap g = bent_grid(rng);
    // Every interior edge passes where the measure's 0 passes too: the
    // conditions were not turned into guards there.
    EXPECT_EQ(found(g, "any_sign", -1.0).size(), interior_edges) << "seed " << seed;
    EXPECT_EQ(found(g, "at_least", 0.0).size(), interior_edges) << "seed " << seed;
    for (const Real t : {1e-9, 0.01, 0.05, 0.2}) {
      const std::vector<TearCandidate> guarded = found(g, "guarded", t);
      expect_same(guarded, found(g, "any_sign", t), "guarded / any_sign");
      if (t < 0.05) {
        // Some edges fail a guard (a corner behind, a face turned off), others pass.
        EXPECT_GT(guarded.size(), 0u) << "seed " << seed << ", threshold " << t;
        EXPECT_LT(guarded.size(), interior_edges) << "seed " << seed << ", threshold " << t;
      }
    }
  }
}

}  // namespace
