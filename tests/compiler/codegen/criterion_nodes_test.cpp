// Criteria with pattern nodes in generated code (golden/ok_criterion_nodes):
// where the pattern does not match (a boundary edge, where a@2 is a; a
// triangle, where three steps around the face return to its dart) a cell
// gives no candidate; elsewhere the measure is the one computed here by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "criterion_nodes.hpp"
#include "rift/io/load_map.hpp"

namespace {

namespace cn = rift::packs::criterion_nodes;
using rift::Dart;
using rift::GMap;
using rift::Orbit;
using rift::Real;
using rift::Vec3;

constexpr Orbit kEdge{0, 2};

/// The least dart of the orbit `o` of d: one name per cell.
Dart least_dart(const GMap& g, Dart d, Orbit o) {
  Dart least = d;
  g.for_each_in_orbit(d, o, [&](Dart x) { least = std::min(least, x); });
  return least;
}

std::vector<rift::TearCandidate> collect(rift::Criterion& criterion, const GMap& g) {
  std::vector<rift::TearCandidate> found;
  criterion.collect(g, found);
  return found;
}

/// On an N x N grid of the unit square, each inner edge's faces have centres
/// 1/N apart; the 4N boundary edges have one face and propose nothing.
void expect_inner_edges_only(int n) {
  GMap g = rift::load_map("grid:quad:" + std::to_string(n) + "x" + std::to_string(n));
  const cn::Pack pack;
  pack.initialise(g);
  cn::FaceDistanceCriterion criterion;
  criterion.initialise(g);
  const auto found = collect(criterion, g);
  int edges = 0;
  int inner = 0;
  g.for_each_cell(kEdge, [&](Dart a) {
    ++edges;
    inner += g.is_free(a, 2) ? 0 : 1;
  });
  EXPECT_EQ(edges, 2 * n * (n + 1));
  EXPECT_EQ(inner, 2 * n * (n - 1));
  ASSERT_EQ(static_cast<int>(found.size()), inner);
  std::set<Dart> edges_seen;
  for (const rift::TearCandidate& c : found) {
    EXPECT_FALSE(g.is_free(c.at, 2)) << "a boundary edge was proposed at dart " << c.at;
    EXPECT_NEAR(c.measure, 1.0 / n, 1e-12);  // the margin over the threshold 0
    edges_seen.insert(least_dart(g, c.at, kEdge));
  }
  EXPECT_EQ(static_cast<int>(edges_seen.size()), inner);  // each inner edge once
}

TEST(CriterionNodes, OnlyInnerEdgesMatchAndTheirMeasureIsTheCentreDistance) {
  expect_inner_edges_only(1);  // a single quad: boundary only, no candidate
  expect_inner_edges_only(2);
  expect_inner_edges_only(3);
}

TEST(CriterionNodes, TheMeasureReadsTheNodeAcrossTheEdge) {
  // Two quads side by side (width 1/2, height 1); move the far corners of the
  // right one: its centre moves by a quarter of the displacement.
  GMap g = rift::load_map("grid:quad:2x1");
  const cn::Pack pack;
  pack.initialise(g);
  auto x = g.embedding<Vec3>("position");
  g.for_each_cell(Orbit{1, 2}, [&](Dart v) {
    if (x[v].x() > 0.99) x[v] += Vec3(0.2, 0.0, 0.4);
  });
  cn::FaceDistanceCriterion criterion;
  criterion.initialise(g);
  const auto found = collect(criterion, g);
  ASSERT_EQ(found.size(), 1u);
  // Centres (0.25, 0.5, 0) and (0.75 + 0.1, 0.5, 0.2).
  EXPECT_NEAR(found[0].measure, Vec3(0.6, 0.0, 0.2).norm(), 1e-12);
}

TEST(CriterionNodes, ApplyMatchesThePatternAgain) {
  GMap g = rift::load_map("grid:quad:2x1");
  const cn::Pack pack;
  pack.initialise(g);
  cn::FaceDistanceCriterion criterion;
  criterion.initialise(g);
  const auto found = collect(criterion, g);
  ASSERT_EQ(found.size(), 1u);
  std::vector<Dart> touched;
  // `apply open_edge at b`: the hook is the node across the edge.
  EXPECT_TRUE(criterion.apply(g, found[0], touched));
  EXPECT_TRUE(g.is_free(found[0].at, 2));
  EXPECT_TRUE(g.check_validity().empty());
  // The edge is now a boundary: the pattern no longer matches, at apply as at collect.
  EXPECT_FALSE(criterion.apply(g, found[0], touched));
  EXPECT_TRUE(collect(criterion, g).empty());
}

TEST(CriterionNodes, NodesAreDistinctDarts) {
  // Quads: c is f's neighbour corner, a side away.
  GMap quads = rift::load_map("grid:quad:2x1");
  const cn::Pack pack;
  pack.initialise(quads);
  cn::NotTriangleCriterion criterion;
  criterion.initialise(quads);
  const auto found = collect(criterion, quads);
  ASSERT_EQ(found.size(), 2u);
  for (const rift::TearCandidate& c : found) {
    const Real side = c.measure;
    EXPECT_TRUE(std::abs(side - 0.5) < 1e-12 || std::abs(side - 1.0) < 1e-12) << side;
  }
  // Triangles: c is f itself, and the match is not injective.
  GMap triangles = rift::load_map("grid:tri:2x2");
  pack.initialise(triangles);
  cn::NotTriangleCriterion on_triangles;
  on_triangles.initialise(triangles);
  EXPECT_TRUE(collect(on_triangles, triangles).empty());
}

}  // namespace
