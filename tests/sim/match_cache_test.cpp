// The interaction match cache: after random unsews and sews, re-matching
// only around the touched darts gives the same matches as matching the
// whole map again, and lost matches have their stored forces reset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>

#include "rift/core/parallel.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/sim/cached_interaction.hpp"

namespace rift {
namespace {

// A bending-like kernel on the edge extremity <2>: matches when the dart is
// 2-sewn, and reads the far vertices of both faces (two links away).
struct HingeKernel {
  struct Match {
    Dart d;
    Slot a, b, far_a, far_b;  // vertex slots
    Slot stored;              // slot of the dart's stored force
  };
  static constexpr Orbit kSupport = Orbit{2};
  static constexpr int kRadius = 3;

  const std::string& name() const { return name_; }
  void initialise(GMap& map) {
    position = map.embedding<Vec3>("position");
    stored = map.add_embedding<Vec3>("f_hinge", Orbit{}, MergePolicy::kKeepFirst, Vec3::Zero());
  }
  bool match(const GMap& map, Dart d, Match& m) const {
    const Dart e = map.alpha(d, 2);
    if (e == d) return false;
    // The owner is the smaller dart of the pair, so a match is unique.
    const Dart lo = std::min(d, e);
    const Dart hi = std::max(d, e);
    m = {lo,
         position.slot(lo),
         position.slot(map.alpha(lo, 0)),
         position.slot(map.alpha(map.alpha(lo, 1), 0)),
         position.slot(map.alpha(map.alpha(hi, 1), 0)),
         stored.slot(lo)};
    return true;
  }
  void add_forces(const Match& m, const ForceInput& in, Vec3* f, bool store) {
    const Vec3 pull = in.x[m.far_b] - in.x[m.far_a];
    f[m.far_a] += pull;
    f[m.far_b] -= pull;
    if (store) stored.values()[m.stored] = pull;
  }
  void reset_stored(const Match& m) { stored.values()[m.stored] = Vec3::Zero(); }
  Real energy(const Match&, const ForceInput&) const { return 0; }

  std::string name_ = "hinge";
  Embedding<Vec3> position, stored;
};

using Hinge = CachedInteraction<HingeKernel>;

// An 8×8 quad grid with its hinges set up, and the match and lost callbacks
// of MatchCache for caches built beside the interaction's own.
struct HingeGrid {
  GMap map = assemble_gmap(make_generated_mesh("grid:quad:8x8"));
  Hinge hinge;
  HingeGrid() { hinge.initialise(map); }
  auto match() {
    return [this](const GMap& m, Dart x, HingeKernel::Match& out) {
      return hinge.kernel().match(m, x, out);
    };
  }
  static auto lost() {
    return [](const HingeKernel::Match&, bool) {};
  }
  /// Two caches of the grid's hinges hold the same matches, with the same
  /// owners, in the same order (`step`: where, in the failure's message).
  static void expect_same(const MatchCache<HingeKernel::Match>& a,
                          const MatchCache<HingeKernel::Match>& b, int step) {
    ASSERT_EQ(a.size(), b.size()) << "step " << step;
    for (std::size_t e = 0; e < b.size(); ++e) {
      ASSERT_EQ(a.owners()[e], b.owners()[e]) << "step " << step << " entry " << e;
      ASSERT_EQ(std::memcmp(&a.matches()[e], &b.matches()[e], sizeof(HingeKernel::Match)), 0)
          << "step " << step << " entry " << e;
    }
  }
};

// The same kernel with its force targets: CachedInteraction scatters it in
// the order of a ScatterColouring.
struct ColouredHingeKernel : HingeKernel {
  static constexpr int kForceTerms = 2;
  void force_targets(const Match& m, Slot* out) const {
    out[0] = m.far_a;
    out[1] = m.far_b;
  }
  void add_forces_all(std::span<const Match> ms, const ForceInput& in, Vec3* f, bool store) {
    for (const Match& m : ms)
      add_forces(m, in, f, store);
  }
  void add_forces_at(std::span<const Match> ms, const std::uint32_t* at, std::size_t n,
                     const ForceInput& in, Vec3* f, bool store) {
    for (std::size_t i = 0; i < n; ++i)
      add_forces(ms[at[i]], in, f, store);
  }
};
using ColouredHinge = CachedInteraction<ColouredHingeKernel>;

std::multiset<std::tuple<Dart, Slot, Slot, Slot, Slot>> contents(const Hinge& h) {
  std::multiset<std::tuple<Dart, Slot, Slot, Slot, Slot>> s;
  for (const auto& m : h.cache().matches())
    s.insert({m.d, m.a, m.b, m.far_a, m.far_b});
  return s;
}

class MatchCacheTest : public ::testing::TestWithParam<const char*> {};

TEST_P(MatchCacheTest, LocalRematchEqualsFullRematch) {
  GMap map = assemble_gmap(make_generated_mesh(GetParam()));
  Hinge local;
  local.initialise(map);
  const std::size_t initial = local.active_matches();
  EXPECT_GT(initial, 0u);
  std::mt19937 rng(11);
  std::uniform_int_distribution<Dart> pick(0, static_cast<Dart>(map.capacity() - 1));
  const int n = map.dimension();
  std::vector<std::pair<Dart, Dart>> undone;
  for (int step = 0; step < 120; ++step) {
    std::vector<Dart> touched;
    const Dart d = pick(rng);
    const bool resew = step % 3 == 2 && !undone.empty();
    if (resew) {
      const auto [a, b] = undone.back();
      undone.pop_back();
      if (!map.sew(a, b, n)) continue;
      map.for_each_in_orbit(a, Orbit::sewing(n, n), [&](Dart x) {
        touched.push_back(x);
        touched.push_back(map.alpha(x, n));
      });
    } else {
      if (map.is_free(d, n)) continue;
      undone.emplace_back(d, map.alpha(d, n));
      map.for_each_in_orbit(d, Orbit::sewing(n, n), [&](Dart x) {
        touched.push_back(x);
        touched.push_back(map.alpha(x, n));
      });
      map.unsew(d, n);
    }
    // The simulation passes whole vertex orbits of touched darts.
    std::vector<Dart> region;
    for (Dart t : touched)
      map.for_each_in_orbit(t, Orbit::cell(0, n), [&](Dart x) { region.push_back(x); });
    local.rematch(map, region);
    Hinge full;
    full.kernel().position = map.embedding<Vec3>("position");
    full.kernel().stored = map.embedding<Vec3>("f_hinge");
    // Rebuild from scratch with the same kernel state.
    MatchCache<HingeKernel::Match> fresh;
    fresh.build(map, Orbit{2}, [&](const GMap& m, Dart x, HingeKernel::Match& out) {
      return full.kernel().match(m, x, out);
    });
    std::multiset<std::tuple<Dart, Slot, Slot, Slot, Slot>> expected;
    for (const auto& m : fresh.matches())
      expected.insert({m.d, m.a, m.b, m.far_a, m.far_b});
    ASSERT_EQ(contents(local), expected) << GetParam() << " step " << step;
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, MatchCacheTest,
                         ::testing::Values("grid:quad:4x4", "grid:mix:3x3"));

/// Unsews a random interior edge of `map` on two steps out of three and sews
/// the latest one back on the third, `steps` times; after each change calls
/// `changed(step, region)` with the darts of the vertices around it, the
/// region a re-match after that rewrite must look at.
template <class F>
void tear_and_mend_at_random(GMap& map, unsigned seed, int steps, F&& changed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<Dart> pick(0, static_cast<Dart>(map.capacity() - 1));
  std::vector<std::pair<Dart, Dart>> undone;
  for (int step = 0; step < steps; ++step) {
    std::vector<Dart> touched;
    if (step % 3 == 2 && !undone.empty()) {
      const auto [a, b] = undone.back();
      undone.pop_back();
      if (!map.sew(a, b, 2)) continue;
      map.for_each_in_orbit(a, Orbit::sewing(2, 2), [&](Dart x) {
        touched.push_back(x);
        touched.push_back(map.alpha(x, 2));
      });
    } else {
      const Dart d = pick(rng);
      if (map.is_free(d, 2)) continue;
      undone.emplace_back(d, map.alpha(d, 2));
      map.for_each_in_orbit(d, Orbit::sewing(2, 2), [&](Dart x) {
        touched.push_back(x);
        touched.push_back(map.alpha(x, 2));
      });
      map.unsew(d, 2);
    }
    std::vector<Dart> region;
    for (Dart t : touched)
      map.for_each_in_orbit(t, Orbit::cell(0, 2), [&](Dart x) { region.push_back(x); });
    changed(step, region);
  }
}

// After every local re-match the colouring still covers each match once and
// no two blocks of one colour share a vertex, and the forces are the same
// bits on 1 and 3 threads (blocks of 4 matches: many blocks, many colours).
TEST(MatchCache, TheScatterColouringFollowsLocalRematches) {
  GMap map = assemble_gmap(make_generated_mesh("grid:quad:12x12"));
  ColouredHinge hinge;
  hinge.set_scatter_block(4);
  hinge.initialise(map);
  auto targets = [&](std::size_t e, Slot* out) {
    hinge.kernel().force_targets(hinge.cache().matches()[e], out);
  };
  ASSERT_EQ(hinge.colouring().check(hinge.active_matches(), 2, targets), "");
  EXPECT_GT(hinge.colouring().colours(), 1u);
  tear_and_mend_at_random(map, 5, 200, [&](int step, const std::vector<Dart>& region) {
    hinge.rematch(map, region);
    EXPECT_EQ(hinge.colouring().check(hinge.active_matches(), 2, targets), "") << "step " << step;
  });
  EXPECT_GT(hinge.colouring().blocks() * 4, hinge.active_matches()) << "pending became blocks";
  auto& x = map.embedding<Vec3>("position").values();
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] += Vec3(1e-3 * std::sin(3.0 * i), 1e-5 * std::cos(7.0 * i), 1e-7 * i);
  const std::vector<Vec3> v(x.size(), Vec3::Zero());
  std::vector<Vec3> one(x.size(), Vec3::Zero()), three(x.size(), Vec3::Zero());
  set_thread_count(1);
  hinge.add_forces({x.data(), v.data()}, one.data(), false);
  set_thread_count(3);
  hinge.add_forces({x.data(), v.data()}, three.data(), false);
  set_thread_count(0);
  EXPECT_EQ(std::memcmp(one.data(), three.data(), one.size() * sizeof(Vec3)), 0);
  // The same forces as a plain loop over the matches (up to rounding).
  std::vector<Vec3> plain(x.size(), Vec3::Zero());
  for (const auto& m : hinge.cache().matches())
    hinge.kernel().add_forces(m, {x.data(), v.data()}, plain.data(), false);
  for (std::size_t i = 0; i < x.size(); ++i)
    EXPECT_LE((plain[i] - one[i]).norm(), 1e-12 * (1 + plain[i].norm())) << i;
}

// A cache indexes its owners by dart at its first rematch or when asked: an
// interaction on a map that is rewritten asks at set-up (its first tear then
// costs what it touches), one on a map never rewritten keeps no index. That
// index, made from the owners
// after the build, must be the one the build itself would have made: through
// the same tears and sews, a cache indexed at its build and one indexed at its
// first rematch hold the same matches, with the same owners, in the same order.
TEST(MatchCache, AnOwnerIndexMadeAtTheFirstTearEqualsOneMadeAtTheBuild) {
  HingeGrid grid;
  GMap& map = grid.map;
  const Hinge& hinge = grid.hinge;
  auto match = grid.match();
  auto lost = HingeGrid::lost();
  MatchCache<HingeKernel::Match> eager, lazy;
  eager.build(map, Orbit{2}, match);
  eager.index_owners(map);
  lazy.build(map, Orbit{2}, match);
  EXPECT_TRUE(eager.indexes_owners());
  EXPECT_FALSE(lazy.indexes_owners());
  EXPECT_TRUE(hinge.cache().indexes_owners()) << "a rewritten map's cache indexed at set-up";
  GMap still = assemble_gmap(make_generated_mesh("grid:quad:8x8"));
  Hinge frozen;
  frozen.set_rewrites(false);
  frozen.initialise(still);
  EXPECT_FALSE(frozen.cache().indexes_owners()) << "a map never rewritten needs no index";
  HingeGrid::expect_same(lazy, eager, -1);
  int rematches = 0;
  tear_and_mend_at_random(map, 23, 150, [&](int step, const std::vector<Dart>& region) {
    eager.rematch(map, Orbit{2}, HingeKernel::kRadius, region, match, lost);
    lazy.rematch(map, Orbit{2}, HingeKernel::kRadius, region, match, lost);
    ++rematches;
    EXPECT_TRUE(lazy.indexes_owners());
    HingeGrid::expect_same(lazy, eager, step);
  });
  EXPECT_GT(rematches, 50);
  EXPECT_NE(lazy.size(), 0u);
}

// The owner index is an array by dart or, for an interaction owning few
// darts, a hash table (owner_index.hpp). Through the same tears and sews, a
// cache of each kind holds the same matches, with the same owners, in the
// same order: the kind changes memory, never the matches.
TEST(MatchCache, AHashedOwnerIndexGivesTheMatchesOfAnArrayIndex) {
  HingeGrid grid;
  GMap& map = grid.map;
  const Hinge& hinge = grid.hinge;
  auto match = grid.match();
  auto lost = HingeGrid::lost();
  MatchCache<HingeKernel::Match> array, hashed;
  array.force_sparse_index(false);
  hashed.force_sparse_index(true);
  array.build(map, Orbit{2}, match);
  hashed.build(map, Orbit{2}, match);
  array.index_owners(map);
  hashed.index_owners(map);
  EXPECT_FALSE(array.sparse_index());
  EXPECT_TRUE(hashed.sparse_index());
  // Hinges own one dart in four or so: the cache's own choice is the array.
  EXPECT_FALSE(hinge.cache().sparse_index());
  int rematches = 0;
  tear_and_mend_at_random(map, 31, 150, [&](int step, const std::vector<Dart>& region) {
    array.rematch(map, Orbit{2}, HingeKernel::kRadius, region, match, lost);
    hashed.rematch(map, Orbit{2}, HingeKernel::kRadius, region, match, lost);
    ++rematches;
    HingeGrid::expect_same(hashed, array, step);
  });
  EXPECT_GT(rematches, 50);
  EXPECT_NE(array.size(), 0u);
}

// The index itself against a plain map, through random owners, moves and
// erasures that wrap around the table and shift probe chains back.
TEST(OwnerIndex, FindsWhatWasSetThroughErasuresInBothKinds) {
  for (const bool sparse : {false, true}) {
    std::mt19937 rng(7);
    std::vector<Dart> owners;
    for (Dart d = 0; d < 300; d += 3)
      owners.push_back(d);
    OwnerIndex index;
    index.build(owners, 2000, sparse);
    EXPECT_EQ(index.sparse(), sparse);
    std::map<Dart, std::uint32_t> expected;
    for (std::size_t e = 0; e < owners.size(); ++e)
      expected[owners[e]] = static_cast<std::uint32_t>(e);
    std::uniform_int_distribution<Dart> dart(0, 1999);
    for (int k = 0; k < 20000; ++k) {
      const Dart d = dart(rng);
      switch (rng() % 3) {
        case 0:
          index.set(d, static_cast<std::uint32_t>(k));
          expected[d] = static_cast<std::uint32_t>(k);
          break;
        case 1:
          index.erase(d);
          expected.erase(d);
          break;
        default: {
          const auto it = expected.find(d);
          ASSERT_EQ(index.find(d), it == expected.end() ? OwnerIndex::kNone : it->second)
              << (sparse ? "hashed" : "array") << ", operation " << k << ", dart " << d;
        }
      }
    }
    ASSERT_EQ(index.size(), expected.size());
    for (Dart d = 0; d < 2000; ++d) {
      const auto it = expected.find(d);
      ASSERT_EQ(index.find(d), it == expected.end() ? OwnerIndex::kNone : it->second) << d;
    }
  }
  // Left to choose, the smaller kind: 16 cells of 8 bytes against 4 bytes a dart.
  OwnerIndex few, many;
  const std::vector<Dart> one{5};
  few.build(one, 33);
  many.build(one, 32);
  EXPECT_TRUE(few.sparse());
  EXPECT_FALSE(many.sparse());
  EXPECT_TRUE(OwnerIndex::hashes(1000, 8193));  // a table of 2048 cells
  EXPECT_FALSE(OwnerIndex::hashes(1000, 4096));
}

TEST(MatchCache, LostMatchesResetTheirStoredForces) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 2, 1));
  Hinge hinge;
  hinge.initialise(map);
  ASSERT_EQ(hinge.active_matches(), 2u);  // one inner edge, two extremities
  auto& x = map.embedding<Vec3>("position").values();
  std::vector<Vec3> v(x.size(), Vec3::Zero()), f(x.size(), Vec3::Zero());
  hinge.add_forces({x.data(), v.data()}, f.data(), true);
  auto stored = map.embedding<Vec3>("f_hinge");
  Dart inner = kNoDart;
  map.for_each_dart([&](Dart d) {
    if (inner == kNoDart && !map.is_free(d, 2)) inner = d;
  });
  const Dart owner = hinge.cache().owners()[0];
  EXPECT_GT(stored[owner].norm(), 0);
  std::vector<Dart> region;
  map.for_each_in_orbit(inner, Orbit{0, 2}, [&](Dart d) { region.push_back(d); });
  map.unsew(inner, 2);
  hinge.rematch(map, region);
  EXPECT_EQ(hinge.active_matches(), 0u);
  EXPECT_EQ(stored[owner], Vec3::Zero());
}

}  // namespace
}  // namespace rift
