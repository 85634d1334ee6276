// Random sequences of G-map unsews and sews keep the map valid, and the cell
// counts agree with a reference count by brute-force closure.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"

namespace rift {
namespace {

std::size_t reference_cell_count(const GMap& map, Orbit o) {
  std::set<Dart> seen;
  std::size_t cells = 0;
  map.for_each_dart([&](Dart d) {
    if (seen.count(d)) return;
    ++cells;
    std::vector<Dart> todo{d};
    seen.insert(d);
    while (!todo.empty()) {
      const Dart x = todo.back();
      todo.pop_back();
      for (int i = 0; i <= map.dimension(); ++i) {
        if (o.contains(i) && seen.insert(map.alpha(x, i)).second) todo.push_back(map.alpha(x, i));
      }
    }
  });
  return cells;
}

void run_random_sequence(const char* spec, unsigned seed, int steps) {
  GMap map = assemble_gmap(make_generated_mesh(spec));
  map.add_embedding<Real>("corner_mass", Orbit::cell(0, map.dimension()).without(map.dimension()),
                          MergePolicy::kSum, 1.0);
  std::mt19937 rng(seed);
  const int n = map.dimension();
  std::uniform_int_distribution<Dart> pick(0, static_cast<Dart>(map.capacity() - 1));
  std::uniform_int_distribution<int> pick_dim(0, n);
  int sews = 0, unsews = 0;
  for (int step = 0; step < steps; ++step) {
    const Dart d = pick(rng);
    const int i = pick_dim(rng);
    if (!map.is_free(d, i)) {
      map.unsew(d, i);
      ++unsews;
    } else {
      // Try a few partners; most random pairs are not isomorphic.
      for (int attempt = 0; attempt < 20; ++attempt) {
        const Dart e = pick(rng);
        if (map.why_not_sewable(d, e, i).empty()) {
          ASSERT_TRUE(map.sew(d, e, i));
          ++sews;
          break;
        }
        EXPECT_FALSE(map.sew(d, e, i));
      }
    }
    const auto problems = map.check_validity(3);
    ASSERT_TRUE(problems.empty()) << spec << " step " << step << ": " << problems.front();
    for (int k = 0; k <= n; ++k) {
      ASSERT_EQ(map.count_cells_of_dimension(k), reference_cell_count(map, Orbit::cell(k, n)))
          << spec << " step " << step << " cells of dimension " << k;
    }
  }
  EXPECT_GT(unsews, 0);
  EXPECT_GT(sews, 0);
}

TEST(RandomSewUnsew, QuadGrid) {
  run_random_sequence("grid:quad:3x3", 1, 600);
}
TEST(RandomSewUnsew, MixGrid) {
  run_random_sequence("grid:mix:3x2", 2, 300);
}
TEST(RandomSewUnsew, HexBlock) {
  run_random_sequence("block:hex:2x1x1", 3, 200);
}
TEST(RandomSewUnsew, TetBlock) {
  run_random_sequence("block:tet:1x1x1", 4, 400);
}

}  // namespace
}  // namespace rift
