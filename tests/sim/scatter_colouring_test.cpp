// The coloured scatter order (rift/sim/scatter_colouring.hpp): no vertex is
// touched by two blocks of one colour, every entry is scattered once, after
// any sequence of the match cache's changes, and the per-vertex sums are the
// same bits on any number of threads.
#include "rift/sim/scatter_colouring.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "rift/core/parallel.hpp"
#include "thread_count_guard.hpp"

namespace rift {
namespace {

using test::ThreadCountGuard;

using Spring = std::array<Slot, 2>;

/// Springs between the neighbours of an n×n grid of vertices, row by row
/// (the order of a mesh's elements), both directions of each edge as the
/// paper's atomic springs.
std::vector<Spring> grid_springs(Slot n) {
  std::vector<Spring> s;
  for (Slot r = 0; r < n; ++r) {
    for (Slot c = 0; c < n; ++c) {
      const Slot v = r * n + c;
      if (c + 1 < n) {
        s.push_back({v, v + 1});
        s.push_back({v + 1, v});
      }
      if (r + 1 < n) {
        s.push_back({v, v + n});
        s.push_back({v + n, v});
      }
    }
  }
  return s;
}

void build(ScatterColouring& c, const std::vector<Spring>& springs) {
  c.build(springs.size(), 2, [&](std::size_t e, Slot* out) {
    out[0] = springs[e][0];
    out[1] = springs[e][1];
  });
}

std::string check(const ScatterColouring& c, const std::vector<Spring>& springs) {
  return c.check(springs.size(), 2, [&](std::size_t e, Slot* out) {
    out[0] = springs[e][0];
    out[1] = springs[e][1];
  });
}

/// Per vertex, the sum of its springs' terms (of very different magnitudes,
/// so that any change of order changes the bits) in the colouring's order.
std::vector<Real> scatter(const ScatterColouring& c, const std::vector<Spring>& springs,
                          std::size_t vertices, std::vector<int>* visits = nullptr) {
  std::vector<Real> sum(vertices, 0);
  if (visits) visits->assign(springs.size(), 0);
  auto body = [&](const std::uint32_t* entries, std::size_t n, bool consecutive) {
    for (std::size_t i = 0; i < n; ++i) {
      // A consecutive block is read from its first entry only (a frozen
      // colouring keeps no other).
      const std::uint32_t e = consecutive ? entries[0] + static_cast<std::uint32_t>(i) : entries[i];
      if (visits) ++(*visits)[e];
      const Real term = std::ldexp(1.0 + 1e-3 * e, static_cast<int>(e % 61) - 30);
      sum[springs[e][0]] += term;
      sum[springs[e][1]] -= 0.5 * term;
    }
  };
  c.run(body);
  return sum;
}

/// One random change of the matches, as a tear's re-match makes them, applied
/// to the colouring and mirrored in `springs`: an erase (swap-and-pop, as
/// MatchCache::erase), a replacement or, when `may_insert`, an insertion.
void random_change(ScatterColouring& c, std::vector<Spring>& springs, Slot& vertices,
                   std::mt19937& rng, bool may_insert = true) {
  const int what = static_cast<int>(rng() % (may_insert ? 3 : 2));
  const auto e = static_cast<std::uint32_t>(rng() % springs.size());
  if (what == 0 && springs.size() > 1) {
    const auto last = static_cast<std::uint32_t>(springs.size() - 1);
    c.erase(e, last);
    springs[e] = springs[last];
    springs.pop_back();
  } else if (what == 1) {
    // Matched again: half the time the same vertices, else one moved to
    // another vertex, sometimes a new one (a split).
    Spring s = springs[e];
    const bool same = rng() % 2 == 0;
    if (!same) s[rng() % 2] = rng() % 8 == 0 ? vertices++ : static_cast<Slot>(rng() % vertices);
    c.replace(e, same, s);
    springs[e] = s;
  } else {
    const Spring s{static_cast<Slot>(rng() % vertices), static_cast<Slot>(rng() % vertices)};
    c.insert(static_cast<std::uint32_t>(springs.size()), s);
    springs.push_back(s);
  }
}

TEST(ScatterColouring, AGridNeedsFewColoursAndNoBlocksOfOneColourShareAVertex) {
  const std::vector<Spring> springs = grid_springs(60);
  for (std::size_t block : {16u, 256u, 2048u}) {
    ScatterColouring c(block);
    build(c, springs);
    EXPECT_EQ(check(c, springs), "") << block;
    EXPECT_EQ(c.blocks(), (springs.size() + block - 1) / block);
    EXPECT_EQ(c.pending(), 0u);
    EXPECT_LE(c.colours(), 6u) << block;
    std::vector<int> visits;
    scatter(c, springs, 3600, &visits);
    for (int v : visits)
      ASSERT_EQ(v, 1);
  }
}

TEST(ScatterColouring, FollowsErasesReplacementsAndInsertionsAndSumsTheSameOnAnyThreads) {
  ThreadCountGuard guard;
  std::vector<Spring> springs = grid_springs(40);
  Slot vertices = 1600;
  ScatterColouring c(16);
  build(c, springs);
  std::mt19937 rng(3);
  for (int step = 0; step < 3000; ++step) {
    random_change(c, springs, vertices, rng);
    if (step % 50 == 0 || step > 2950) {
      ASSERT_EQ(check(c, springs), "") << "step " << step;
    }
  }
  EXPECT_GT(c.blocks(), springs.size() / 16) << "pending entries became blocks";
  std::vector<int> visits;
  set_thread_count(1);
  const std::vector<Real> one = scatter(c, springs, vertices, &visits);
  for (int v : visits)
    ASSERT_EQ(v, 1);
  for (int threads : {2, 8}) {
    set_thread_count(threads);
    const std::vector<Real> many = scatter(c, springs, vertices);
    EXPECT_EQ(std::memcmp(one.data(), many.data(), one.size() * sizeof(Real)), 0) << threads;
  }
}

// A small map's colouring is one block holding every match: through erases,
// replacements and insertions it stays one consecutive block with nothing
// pending (the kernels' fast path), until it outgrows block(); then the
// general bookkeeping takes over, still correct.
TEST(ScatterColouring, OneBlockHoldingEveryEntryStaysConsecutiveThroughChanges) {
  ThreadCountGuard guard;
  std::vector<Spring> springs = grid_springs(10);  // 360 springs
  Slot vertices = 100;
  constexpr std::size_t kBlock = 400;
  ScatterColouring c(kBlock);
  build(c, springs);
  ASSERT_EQ(c.blocks(), 1u);
  std::mt19937 rng(5);
  auto all_consecutive = [&] {
    bool consecutive = true;
    auto body = [&](const std::uint32_t*, std::size_t, bool block_consecutive) {
      consecutive = consecutive && block_consecutive;
    };
    c.run(body);
    return consecutive;
  };
  for (int step = 0; step < 2000; ++step) {
    random_change(c, springs, vertices, rng, springs.size() < kBlock);
    ASSERT_EQ(check(c, springs), "") << "step " << step;
    ASSERT_EQ(c.blocks(), 1u) << "step " << step;
    ASSERT_EQ(c.pending(), 0u) << "step " << step;
    ASSERT_TRUE(all_consecutive()) << "step " << step;
  }
  // Past block() entries, new blocks: on the vertices the splits above
  // added (which only the one block's replacements marked), their colours
  // must keep apart from the one block's.
  const Slot grid = 100;
  ASSERT_GT(vertices, grid + 10);
  while (springs.size() <= 3 * kBlock) {
    const Spring s{static_cast<Slot>(grid + rng() % (vertices - grid)),
                   static_cast<Slot>(grid + rng() % (vertices - grid))};
    c.insert(static_cast<std::uint32_t>(springs.size()), s);
    springs.push_back(s);
  }
  for (int step = 0; step < 1000; ++step) {
    random_change(c, springs, vertices, rng);
    if (step % 20 == 0) {
      ASSERT_EQ(check(c, springs), "") << "step " << step;
    }
  }
  EXPECT_GT(c.blocks(), 1u);
  EXPECT_EQ(check(c, springs), "");
  std::vector<int> visits;
  set_thread_count(1);
  const std::vector<Real> one = scatter(c, springs, vertices, &visits);
  for (int v : visits)
    ASSERT_EQ(v, 1);
  set_thread_count(4);
  const std::vector<Real> four = scatter(c, springs, vertices);
  EXPECT_EQ(std::memcmp(one.data(), four.data(), one.size() * sizeof(Real)), 0);
}

TEST(ScatterColouring, BlocksThatTouchEverythingRunOnOneThreadAfterTheColours) {
  // Every spring touches vertex 0: no two blocks may share a colour, so
  // beyond kMaxColours blocks the rest must run serially.
  std::vector<Spring> springs;
  for (Slot v = 1; v <= 200; ++v)
    springs.push_back({0, v});
  ScatterColouring c(2);
  build(c, springs);
  EXPECT_EQ(c.colours(), static_cast<std::size_t>(ScatterColouring::kMaxColours));
  EXPECT_EQ(check(c, springs), "");
  std::vector<int> visits;
  scatter(c, springs, 201, &visits);
  for (int v : visits)
    ASSERT_EQ(v, 1);
}

// A frozen colouring keeps only each block's first entry (a build's blocks
// are consecutive): the same blocks, colours and sums, bit for bit, on any
// number of threads, and a change is refused.
TEST(ScatterColouring, AFrozenColouringScattersTheSameSumsFromItsBlocksFirstEntries) {
  const std::vector<Spring> springs = grid_springs(40);
  for (std::size_t block : {16u, 300u}) {
    ScatterColouring live(block), frozen(block);
    build(live, springs);
    build(frozen, springs);
    frozen.freeze();
    ASSERT_TRUE(frozen.frozen());
    EXPECT_EQ(check(frozen, springs), "") << block;
    EXPECT_EQ(frozen.blocks(), live.blocks());
    EXPECT_EQ(frozen.colours(), live.colours());
    EXPECT_EQ(frozen.entries(), springs.size());
    std::vector<int> visits;
    const std::vector<Real> expected = scatter(live, springs, 1600);
    ThreadCountGuard guard;
    for (int threads : {1, 3}) {
      set_thread_count(threads);
      const std::vector<Real> got = scatter(frozen, springs, 1600, &visits);
      for (std::size_t v = 0; v < got.size(); ++v)
        ASSERT_EQ(std::memcmp(&got[v], &expected[v], sizeof(Real)), 0) << "vertex " << v;
      for (int n : visits)
        ASSERT_EQ(n, 1);
    }
    const Spring s{0, 1};
    EXPECT_THROW(frozen.insert(static_cast<std::uint32_t>(springs.size()), s), std::logic_error);
  }
}

}  // namespace
}  // namespace rift
