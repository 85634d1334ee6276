// A criterion's apply arguments travel with its candidates:
// golden/ok_criterion_payload/case.rules compiled by riftc. Its rules write
// their arguments into the face they apply at; the positions move between
// collect() and apply(), and the faces must hold the values of the state at
// detection, computed here by hand from the criterion's formulas.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "payload.hpp"
#include "rift/generated/candidate_payload.hpp"
#include "rift/io/load_map.hpp"

namespace {

namespace pp = rift::packs::payload;
using rift::ComponentUse;
using rift::Dart;
using rift::GMap;
using rift::Mat3;
using rift::Real;
using rift::SceneParam;
using rift::TearCandidate;
using rift::Value;
using rift::Vec3;

/// What rule `record` should receive at face dart f, from the state now.
struct Expected {
  Vec3 n, p;
  Real offset;
  std::int64_t k;
  bool flag;
  Mat3 m;
  Vec3 t;
};

Expected by_hand(const GMap& g, Dart f, Real width, std::int64_t scale) {
  const auto x = g.embedding<Vec3>("position");
  const Vec3 e1 = x[g.alpha(f, 0)] - x[f];
  const Vec3 e2 = x[g.alpha(g.alpha(f, 1), 0)] - x[f];
  Expected e;
  e.n = e1.cross(e2).normalized();
  e.p = x[f];
  e.offset = e1.norm() - width + static_cast<Real>(scale);
  e.k = static_cast<std::int64_t>(static_cast<Real>(scale) * e2.norm());  // int() truncates
  e.flag = e1.dot(e2) > 0.0;
  e.m = e1 * e2.transpose() + Mat3::Identity();
  e.t = e2.cross(e1);
  return e;
}

/// A 3x3 quad grid, jittered so that no two faces give the same values and
/// some corners are acute (flag true), some obtuse.
GMap jittered_grid(std::mt19937& rng) {
  GMap g = rift::load_map("grid:quad:3x3");
  pp::Pack().initialise(g);
  auto x = g.embedding<Vec3>("position");
  std::uniform_real_distribution<Real> jitter(-0.08, 0.08);
  g.for_each_cell(rift::Orbit{1, 2}, [&](Dart v) { x[v] += Vec3(jitter(rng), jitter(rng), 0.0); });
  return g;
}

void move_everything(GMap& g) {
  auto x = g.embedding<Vec3>("position");
  g.for_each_cell(rift::Orbit{1, 2},
                  [&](Dart v) { x[v] = Vec3(2.0 * x[v].y() + 0.3, -x[v].x(), 0.1 * x[v].x()); });
}

ComponentUse use(const char* name, Real width) {
  ComponentUse u;
  u.name = name;
  u.params["width"] = SceneParam{Value(width), 0};
  return u;
}

TEST(CriterionPayload, EveryArgumentIsTheValueAtDetection) {
  std::mt19937 rng(2026);
  GMap g = jittered_grid(rng);
  const Real width = 0.1;  // every first edge (1/3, jittered by at most 0.16) passes
  const std::int64_t scale = 10;
  auto criterion = pp::Pack().make_criterion(use("long_side", width));
  criterion->initialise(g);
  std::vector<TearCandidate> found;
  criterion->collect(g, found);
  ASSERT_EQ(found.size(), 9u);  // one per face
  std::vector<Expected> expected;
  for (const TearCandidate& c : found) {
    EXPECT_EQ(c.payload_reals, 9u);  // n, p: 3 each; offset, k, flag: 1 each
    expected.push_back(by_hand(g, c.at, width, scale));
  }
  int acute = 0;
  for (const Expected& e : expected)
    acute += e.flag;
  EXPECT_GT(acute, 0);
  EXPECT_LT(acute, 9);
  // What apply() would compute now differs from what the candidate carries.
  move_everything(g);
  const auto n = g.embedding<Vec3>("got_n");
  const auto p = g.embedding<Vec3>("got_p");
  const auto offset = g.embedding<Real>("got_offset");
  const auto k = g.embedding<std::int64_t>("got_k");
  const auto flag = g.embedding<rift::Bool>("got_flag");
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Dart f = found[i].at;
    const Expected& e = expected[i];
    ASSERT_NE(by_hand(g, f, width, scale).p, e.p);
    std::vector<Dart> touched;
    ASSERT_TRUE(criterion->apply(g, found[i], touched)) << "face of dart " << f;
    // The same formulas in the same order: the same bits, except where
    // Eigen and riftc's C++ may associate a product differently.
    EXPECT_LT((n[f] - e.n).norm(), 1e-15) << "face of dart " << f;
    EXPECT_EQ(p[f], e.p) << "face of dart " << f;
    EXPECT_NEAR(offset[f], e.offset, 1e-15) << "face of dart " << f;
    EXPECT_EQ(k[f], e.k) << "face of dart " << f;
    EXPECT_EQ(static_cast<bool>(flag[f]), e.flag) << "face of dart " << f;
  }
}

TEST(CriterionPayload, AMat3AndAVec3FillThePayload) {
  std::mt19937 rng(7);
  GMap g = jittered_grid(rng);
  auto criterion = pp::Pack().make_criterion(use("framed", 0.0));
  criterion->initialise(g);
  std::vector<TearCandidate> found;
  criterion->collect(g, found);
  ASSERT_EQ(found.size(), 9u);
  std::vector<Expected> expected;
  for (const TearCandidate& c : found) {
    EXPECT_EQ(c.payload_reals, rift::kCandidatePayloadReals);
    expected.push_back(by_hand(g, c.at, 0.0, 0));
  }
  move_everything(g);
  const auto m = g.embedding<Mat3>("got_m");
  const auto t = g.embedding<Vec3>("got_t");
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Dart f = found[i].at;
    std::vector<Dart> touched;
    ASSERT_TRUE(criterion->apply(g, found[i], touched)) << "face of dart " << f;
    EXPECT_LT((m[f] - expected[i].m).norm(), 1e-15) << "face of dart " << f;
    EXPECT_EQ(t[f], expected[i].t) << "face of dart " << f;
  }
}

TEST(CriterionPayload, ValuesReadBackAsWritten) {
  TearCandidate c;
  Mat3 m;
  m << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  rift::generated::put_payload<Mat3>(c, 0, m);
  rift::generated::put_payload<std::int64_t>(c, 9, -(std::int64_t{1} << 52));
  rift::generated::put_payload<bool>(c, 10, true);
  rift::generated::put_payload<Real>(c, 11, 0.1);
  EXPECT_EQ(c.payload_reals, 12u);
  EXPECT_EQ(rift::generated::payload_as<Mat3>(c, 0), m);
  EXPECT_EQ(rift::generated::payload_as<std::int64_t>(c, 9), -(std::int64_t{1} << 52));
  EXPECT_TRUE(rift::generated::payload_as<bool>(c, 10));
  EXPECT_EQ(rift::generated::payload_as<Real>(c, 11), 0.1);
  const Vec3 v(-1.5, 0.0, 2e-300);
  rift::generated::put_payload<Vec3>(c, 3, v);
  EXPECT_EQ(rift::generated::payload_as<Vec3>(c, 3), v);
  EXPECT_EQ(c.payload_reals, 12u);  // the count never shrinks
}

}  // namespace
