// Lets inside folds in generated code: golden/ok_fold_lets/case.rules
// compiled by riftc. On a grid of squares of side h each value has a closed
// form (a face's corner triangle has twice-area h^2); on a deformed grid the
// pack must give the same sums written in C++ here.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "fold_lets.hpp"
#include "rift/io/load_map.hpp"

namespace {

namespace fl = rift::packs::fold_lets;
using rift::Dart;
using rift::GMap;
using rift::Orbit;
using rift::Real;
using rift::Vec3;

const Orbit kVertex{1, 2};
const Real kSide = 1.0 / 3.0;  // grid:quad:3x3 divides the unit square

/// Twice the area of the corner triangle of dart f's face at f's vertex.
Real corner2(const GMap& g, const rift::Embedding<Vec3>& x, Dart f) {
  const Vec3 e1 = x[g.alpha(f, 0)] - x[f];
  const Vec3 e2 = x[g.alpha(g.alpha(f, 1), 0)] - x[f];
  return e1.cross(e2).norm();
}

/// f(d) for one dart d of each sub-orbit `sub` of v's vertex.
template <class F>
void around(const GMap& g, Dart v, Orbit sub, F&& f) {
  g.for_each_sub_orbit(v, kVertex, sub, f);
}

TEST(FoldLets, InitSumsTheCornersOfAVertexsFaces) {
  GMap g = rift::load_map("grid:quad:3x3");
  fl::declare_embeddings(g);
  fl::run_initialisers(g);
  const auto corners = g.embedding<Real>("corners");
  Real total = 0;
  int vertices = 0;
  g.for_each_cell(kVertex, [&](Dart v) {
    int faces = 0;
    around(g, v, Orbit{0, 1}, [&](Dart) { ++faces; });
    EXPECT_NEAR(corners[v], faces * kSide * kSide, 1e-12) << "vertex of dart " << v;
    total += corners[v];
    ++vertices;
  });
  EXPECT_EQ(vertices, 16);
  EXPECT_NEAR(total, 4.0 * 9.0 * kSide * kSide, 1e-12);  // four corners per square
}

TEST(FoldLets, RuleAndScriptComputeTheirFoldsOnADeformedGrid) {
  GMap g = rift::load_map("grid:quad:3x3");
  fl::declare_embeddings(g);
  auto x = g.embedding<Vec3>("position");
  g.for_each_cell(kVertex, [&](Dart v) {
    const Vec3 p = x[v];
    x[v] = p + Vec3(0.1 * p.y() * p.y(), -0.2 * p.x(), 0.05 * p.x() * p.y());
  });
  fl::run_initialisers(g);
  const auto corners = g.embedding<Real>("corners");
  const auto mark = g.embedding<Real>("mark");
  const auto edges = g.embedding<Real>("edges");
  int checked = 0;
  g.for_each_cell(kVertex, [&](Dart v) {
    Real sum = 0, longest = 0, squares = 0;
    around(g, v, Orbit{0, 1}, [&](Dart f) { sum += corner2(g, x, f); });
    around(g, v, Orbit{2}, [&](Dart e) {
      const Real l = (x[g.alpha(e, 0)] - x[e]).norm();
      longest = std::max(longest, l);
      squares += l * l;
    });
    EXPECT_NEAR(corners[v], sum, 1e-12);
    ASSERT_TRUE(fl::apply_mark_vertex(g, std::span<const Dart>(&v, 1), {}));
    EXPECT_NEAR(mark[v], longest, 1e-12);
    // A script reports whether it applied a rule; this one only sets a value.
    EXPECT_FALSE(fl::apply_count_edges(g, std::span<const Dart>(&v, 1), {}));
    EXPECT_NEAR(edges[v], squares, 1e-12);
    EXPECT_GT(squares, longest * longest);  // at least two edges at every vertex
    ++checked;
  });
  EXPECT_EQ(checked, 16);
}

TEST(FoldLets, RuleAppliesWhereItsWhensHold) {
  GMap g = rift::load_map("grid:quad:3x3");
  fl::declare_embeddings(g);
  auto x = g.embedding<Vec3>("position");
  g.for_each_cell(kVertex, [&](Dart v) { x[v] *= 1.0 + 0.3 * x[v].x(); });
  const auto mark = g.embedding<Real>("mark");
  fl::mark_if_long_args args;
  args.limit = 0.4;
  int applied = 0, refused = 0;
  g.for_each_cell(kVertex, [&](Dart v) {
    Real longest = 0;
    around(g, v, Orbit{2},
           [&](Dart e) { longest = std::max(longest, (x[g.alpha(e, 0)] - x[e]).norm()); });
    const bool ok = fl::apply_mark_if_long(g, std::span<const Dart>(&v, 1), args);
    EXPECT_EQ(ok, longest > args.limit) << "vertex of dart " << v;
    EXPECT_NEAR(mark[v], ok ? 2 * longest : 0.0, 1e-12);
    (ok ? applied : refused) += 1;
  });
  EXPECT_GT(applied, 0);
  EXPECT_GT(refused, 0);
}

TEST(FoldLets, CriterionProposesTheVerticesWithALargeCorner) {
  GMap g = rift::load_map("grid:quad:3x3");
  const fl::Pack pack;
  pack.initialise(g);
  rift::ComponentUse use;
  use.name = "big_corner";
  use.params["limit"] = rift::SceneParam{rift::Value(0.2), 0};
  auto criterion = pack.make_criterion(use);
  criterion->initialise(g);
  std::vector<rift::TearCandidate> found;
  criterion->collect(g, found);
  EXPECT_TRUE(found.empty());  // every corner has twice-area h^2 = 1/9
  // Pull one interior vertex away: the corners next to it grow.
  auto x = g.embedding<Vec3>("position");
  Dart pulled = rift::kNoDart;
  g.for_each_cell(kVertex, [&](Dart v) {
    int faces = 0;
    around(g, v, Orbit{0, 1}, [&](Dart) { ++faces; });
    if (faces == 4 && pulled == rift::kNoDart) pulled = v;
  });
  ASSERT_NE(pulled, rift::kNoDart);
  x[pulled] += Vec3(0.0, 0.0, 1.2);
  std::set<Dart> expected;  // one representative per vertex, as for_each_cell gives them
  g.for_each_cell(kVertex, [&](Dart v) {
    Real largest = 0;
    around(g, v, Orbit{0, 1}, [&](Dart f) { largest = std::max(largest, corner2(g, x, f)); });
    if (largest > 0.2) expected.insert(v);
  });
  ASSERT_FALSE(expected.empty());
  found.clear();
  criterion->collect(g, found);
  std::set<Dart> proposed;
  for (const rift::TearCandidate& c : found)
    proposed.insert(c.at);
  EXPECT_EQ(proposed, expected);
  std::vector<Dart> touched;
  EXPECT_TRUE(criterion->apply(g, found.front(), touched));
}

}  // namespace
