// The injectivity comparisons of a matcher (compiler/lower/distinct_pairs.hpp)
// against every way a pattern's nodes could land on fewer darts: for each
// partition of the nodes whose blocks carry the arcs consistently (each block
// has at most one partner per dimension, both ways: a map where those blocks
// are darts exists, or a larger one containing them), some compared pair must
// share a block. Partitions are enumerated exhaustively, so a missing pair
// shows whatever the union-find does.
#include "lower/distinct_pairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace rift::lower {
namespace {

struct Arc {
  int a, b, dim;
};

MatchPlan plan_of(const std::vector<Arc>& arcs) {
  MatchPlan plan;
  for (const Arc& x : arcs)
    plan.arc_checks.push_back(ArcCheck{x.a, x.b, x.dim});
  return plan;
}

// Whether blocks (block[v] per node) carry the arcs as involutions.
bool consistent(const std::vector<int>& block, const std::vector<Arc>& arcs, int dims) {
  const int blocks = *std::max_element(block.begin(), block.end()) + 1;
  std::vector<std::vector<int>> partner(static_cast<std::size_t>(dims),
                                        std::vector<int>(static_cast<std::size_t>(blocks), -1));
  auto set = [&](int d, int x, int y) {
    int& p = partner[static_cast<std::size_t>(d)][static_cast<std::size_t>(x)];
    if (p != -1 && p != y) return false;
    p = y;
    return true;
  };
  for (const Arc& arc : arcs) {
    const int x = block[static_cast<std::size_t>(arc.a)],
              y = block[static_cast<std::size_t>(arc.b)];
    if (!set(arc.dim, x, y) || !set(arc.dim, y, x)) return false;
  }
  return true;
}

// Every consistent partition with a block of two nodes or more is caught by a
// compared pair; returns the number of such partitions.
int expect_collisions_caught(int nodes, const std::vector<Arc>& arcs, const std::string& what) {
  int dims = 0;
  for (const Arc& a : arcs)
    dims = std::max(dims, a.dim + 1);
  const auto pairs = distinct_pairs(nodes, plan_of(arcs));
  int collapsing = 0;
  // Restricted growth strings: block[0] = 0, block[k] <= 1 + max(block[0..k)).
  std::vector<int> block(static_cast<std::size_t>(nodes), 0);
  for (;;) {
    const int blocks = *std::max_element(block.begin(), block.end()) + 1;
    if (blocks < nodes && consistent(block, arcs, dims)) {
      ++collapsing;
      bool caught = false;
      for (const auto& [a, b] : pairs)
        caught = caught || block[static_cast<std::size_t>(a)] == block[static_cast<std::size_t>(b)];
      std::string shown;
      for (int b : block)
        shown += std::to_string(b) + " ";
      EXPECT_TRUE(caught) << what << ": nodes on darts " << shown << "pass every comparison";
    }
    // The next restricted growth string.
    int k = nodes - 1;
    for (; k > 0; --k) {
      int most = 0;
      for (int j = 0; j < k; ++j)
        most = std::max(most, block[static_cast<std::size_t>(j)]);
      if (block[static_cast<std::size_t>(k)] <= most) break;
    }
    if (k == 0) break;
    ++block[static_cast<std::size_t>(k)];
    for (int j = k + 1; j < nodes; ++j)
      block[static_cast<std::size_t>(j)] = 0;
  }
  return collapsing;
}

// A face of `sides` edges: darts 0 .. 2 sides - 1, alpha_0 then alpha_1 in turn.
std::vector<Arc> face(int sides) {
  std::vector<Arc> arcs;
  for (int k = 0; k < 2 * sides; ++k) {
    if (k % 2 == 0) {
      arcs.push_back({k, k + 1, 0});
    } else {
      arcs.push_back({k, (k + 1) % (2 * sides), 1});
    }
  }
  return arcs;
}

TEST(DistinctPairs, EveryCollapseOfAFaceIsCaught) {
  for (int sides : {1, 2, 3, 4, 5}) {
    const auto arcs = face(sides);
    const int collapsing = expect_collisions_caught(2 * sides, arcs, "face");
    if (sides > 1) {
      EXPECT_GT(collapsing, 0) << sides;  // faces of fewer edges fold onto it
    }
    // Far fewer comparisons than pairs once the face has a few edges.
    const auto pairs = distinct_pairs(2 * sides, plan_of(arcs));
    if (sides == 4) {
      EXPECT_EQ(pairs.size(), 6u);  // instead of 28
    }
  }
}

TEST(DistinctPairs, PathsLoopsAndDanglingNodesKeepTheirComparisons) {
  // a -0- b -1- c: a and c may be one dart (alpha_1 alpha_0 a = a); no arc
  // links the pairs, so all three are compared.
  const std::vector<Arc> path = {{0, 1, 0}, {1, 2, 1}};
  EXPECT_EQ(distinct_pairs(3, plan_of(path)).size(), 3u);
  expect_collisions_caught(3, path, "path");
  // A loop (free dart) and the bending pattern's shape: two faces' corners
  // across an edge, a -2- b, each with its 0- and 1-neighbours.
  expect_collisions_caught(4, {{0, 0, 2}, {0, 1, 0}, {1, 2, 1}, {2, 3, 0}}, "loop");
  expect_collisions_caught(
      7, {{0, 1, 2}, {0, 2, 0}, {0, 3, 1}, {1, 4, 0}, {1, 5, 1}, {3, 6, 0}, {2, 6, 1}}, "bend");
}

TEST(DistinctPairs, ATriangleOfAVolumeAndTwoSewnFaces) {
  // Two triangles sewn along an edge (alpha_2 on the shared edge's darts).
  std::vector<Arc> arcs = face(3);
  for (const Arc& a : face(3))
    arcs.push_back({a.a + 6, a.b + 6, a.dim});
  arcs.push_back({0, 6, 2});
  arcs.push_back({1, 7, 2});
  expect_collisions_caught(12, arcs, "two triangles");
}

}  // namespace
}  // namespace rift::lower
