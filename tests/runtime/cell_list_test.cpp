// CellList (the cells of a map, kept while its links do not change),
// CellCollection (a criterion's cells visited on one thread or on every core)
// and the aggregates over orbits, whose shortcuts must count each embedding
// orbit exactly once.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "rift/core/parallel.hpp"
#include "rift/generated/support.hpp"
#include "rift/gmap/cell_list.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"

namespace rift {
namespace {

std::vector<Dart> cells_by_marks(const GMap& g, Orbit o) {
  std::vector<Dart> out;
  g.for_each_cell(o, [&](Dart d) { out.push_back(d); });
  return out;
}

/// Cuts the map along `count` random interior links of dimension n (unsews),
/// as tears do.
void cut_randomly(GMap& g, int count, std::mt19937& rng) {
  const int n = g.dimension();
  std::uniform_int_distribution<std::size_t> pick(0, g.capacity() - 1);
  for (int done = 0, tries = 0; done < count && tries < 100 * count; ++tries) {
    const Dart d = static_cast<Dart>(pick(rng));
    if (!g.is_alive(d) || g.is_free(d, n)) continue;
    g.unsew(d, n);
    ++done;
  }
}

TEST(CellList, EqualsTheMarkingWalkAndFollowsEveryChangeOfLinks) {
  std::mt19937 rng(7);
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    GMap g = assemble_gmap(make_grid(kind, 12, 9));
    CellList edges, vertices;
    for (int round = 0; round < 4; ++round) {
      EXPECT_EQ(edges.of(g, Orbit{0, 2}), cells_by_marks(g, Orbit{0, 2}));
      EXPECT_EQ(vertices.of(g, Orbit{1, 2}), cells_by_marks(g, Orbit{1, 2}));
      cut_randomly(g, 5, rng);
    }
    EXPECT_EQ(edges.rebuilds(), 4u);
    // A new dart is a new cell.
    const Dart lone = g.create_dart();
    const std::vector<Dart>& with_lone = vertices.of(g, Orbit{1, 2});
    EXPECT_NE(std::find(with_lone.begin(), with_lone.end(), lone), with_lone.end());
    g.delete_dart(lone);
    EXPECT_EQ(vertices.of(g, Orbit{1, 2}), cells_by_marks(g, Orbit{1, 2}));
  }
}

TEST(CellList, KeptWhileOnlyValuesChangeAndRebuiltForAnotherMapOrOrbit) {
  GMap g = assemble_gmap(make_grid(GridKind::Quad, 6, 5));
  CellList list;
  list.of(g, Orbit{1, 2});
  auto x = g.embedding<Vec3>("position");
  ASSERT_TRUE(x);
  x[0] = Vec3(1, 2, 3);  // values and marks are not topology
  g.for_each_cell(Orbit{0, 1}, [](Dart) {});
  list.of(g, Orbit{1, 2});
  EXPECT_EQ(list.rebuilds(), 1u);
  EXPECT_EQ(list.of(g, Orbit{0, 1}), cells_by_marks(g, Orbit{0, 1}));
  EXPECT_EQ(list.rebuilds(), 2u);
  // Another map with the same links and version is still another map.
  GMap h = assemble_gmap(make_grid(GridKind::Tri, 6, 5));
  EXPECT_EQ(list.of(h, Orbit{0, 1}), cells_by_marks(h, Orbit{0, 1}));
  EXPECT_EQ(list.rebuilds(), 3u);
}

/// Every dart's links and liveness, to tell which darts a change touched.
struct LinkSnapshot {
  std::vector<std::array<Dart, kMaxDimension + 1>> links;
  std::vector<bool> alive;

  explicit LinkSnapshot(const GMap& g) {
    for (Dart d = 0; d < g.capacity(); ++d) {
      std::array<Dart, kMaxDimension + 1> l{};
      for (int i = 0; i <= g.dimension(); ++i)
        l[static_cast<std::size_t>(i)] = g.is_alive(d) ? g.alpha(d, i) : kNoDart;
      links.push_back(l);
      alive.push_back(g.is_alive(d));
    }
  }
  /// The darts created, deleted or relinked since `before` was taken.
  static std::vector<Dart> touched(const LinkSnapshot& before, const LinkSnapshot& after) {
    std::vector<Dart> out;
    for (std::size_t d = 0; d < after.links.size(); ++d) {
      if (d >= before.links.size() || before.alive[d] != after.alive[d] ||
          before.links[d] != after.links[d])
        out.push_back(static_cast<Dart>(d));
    }
    return out;
  }
};

// Told which darts each change touched, the lists follow cuts, new and
// deleted darts by walking those darts' orbits only: never built anew, and
// always what a fresh marking walk gives, on surfaces and on a solid, for
// orbits of one, two and three links.
TEST(CellList, FollowsTheChangesItIsToldOfWithoutBuildingAnew) {
  std::mt19937 rng(17);
  std::vector<GMap> maps;
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix})
    maps.push_back(assemble_gmap(make_grid(kind, 14, 11)));
  maps.push_back(assemble_gmap(make_block(BlockKind::Hex, 4, 3, 3)));
  maps.push_back(assemble_gmap(make_block(BlockKind::Tet, 3, 3, 2)));
  for (GMap& g : maps) {
    const int n = g.dimension();
    std::vector<Orbit> orbits = {Orbit{0}, Orbit::cell(0, n), Orbit::cell(1, n),
                                 Orbit::cell(n - 1, n), Orbit::all(n - 1)};
    if (n == 3) orbits.push_back(Orbit{0, 1, 3});
    std::vector<CellList> lists(orbits.size());
    for (std::size_t k = 0; k < orbits.size(); ++k)
      lists[k].of(g, orbits[k]);
    for (int round = 0; round < 6; ++round) {
      const LinkSnapshot before(g);
      const std::uint64_t from = g.topology_version();
      cut_randomly(g, 4, rng);
      if (round % 2 == 1) {
        // A dart made and one deleted (its place reused by the next round's
        // new dart): cells that appear and disappear.
        g.create_dart();
        Dart element = static_cast<Dart>(rng() % g.capacity());
        while (!g.is_alive(element))
          element = static_cast<Dart>((element + 1) % g.capacity());
        std::vector<Dart> cut;
        g.for_each_in_orbit(element, Orbit::all(n - 1), [&](Dart d) { cut.push_back(d); });
        for (Dart d : cut) {
          if (!g.is_free(d, n)) g.unsew(d, n);
        }
        for (Dart d : cut)
          g.delete_dart(d);
      }
      const std::vector<Dart> touched = LinkSnapshot::touched(before, LinkSnapshot(g));
      for (std::size_t k = 0; k < orbits.size(); ++k) {
        lists[k].note_changed(g, touched, from);
        ASSERT_EQ(lists[k].of(g, orbits[k]), cells_by_marks(g, orbits[k]))
            << "dimension " << n << ", orbit " << orbits[k].str() << ", round " << round;
      }
    }
    for (std::size_t k = 0; k < orbits.size(); ++k) {
      EXPECT_EQ(lists[k].rebuilds(), 1u) << orbits[k].str();
      EXPECT_EQ(lists[k].updates(), 6u) << orbits[k].str();
    }
  }
}

// A change the list was not told of, or told of from another version, makes
// it build the list anew rather than follow half of what happened.
TEST(CellList, BuildsAnewAfterAChangeItWasNotToldOf) {
  std::mt19937 rng(5);
  GMap g = assemble_gmap(make_grid(GridKind::Quad, 10, 8));
  CellList list;
  list.of(g, Orbit{1, 2});
  // Not told at all.
  cut_randomly(g, 3, rng);
  EXPECT_EQ(list.of(g, Orbit{1, 2}), cells_by_marks(g, Orbit{1, 2}));
  EXPECT_EQ(list.rebuilds(), 2u);
  // Told of the second of two changes only.
  const std::uint64_t first = g.topology_version();
  cut_randomly(g, 3, rng);
  LinkSnapshot before(g);
  const std::uint64_t second = g.topology_version();
  cut_randomly(g, 3, rng);
  list.note_changed(g, LinkSnapshot::touched(before, LinkSnapshot(g)), second);
  EXPECT_EQ(list.of(g, Orbit{1, 2}), cells_by_marks(g, Orbit{1, 2}));
  EXPECT_EQ(list.rebuilds(), 3u);
  EXPECT_EQ(list.updates(), 0u);
  EXPECT_NE(first, second);
}

/// A stand-in for a generated criterion: candidates at the edges whose first
/// dart is a multiple of 3, measured by the dart, several per cell for some.
void visit_edge(Dart d, std::vector<TearCandidate>& found) {
  if (d % 3 != 0) return;
  TearCandidate c;
  c.at = d;
  c.measure = static_cast<Real>(d);
  found.push_back(c);
  if (d % 7 == 0) found.push_back(c);
}

TEST(CellCollection, CandidatesInTheOrderOfTheCellsWhateverTheThreads) {
  // Enough edges for many blocks, so that every thread gets several.
  GMap g = assemble_gmap(make_grid(GridKind::Mix, 80, 70));
  std::vector<TearCandidate> expected;
  g.for_each_cell(Orbit{0, 2}, [&](Dart d) { visit_edge(d, expected); });
  ASSERT_GT(expected.size(), 4 * kParallelBlock / 3);
  generated::CellCollection collection;
  for (int threads : {1, 2, 3, 8}) {
    set_thread_count(threads);
    for (auto on : {generated::CollectOn::kOneThread, generated::CollectOn::kEveryCore}) {
      std::vector<TearCandidate> got(1);  // what is already there stays first
      collection.collect(g, Orbit{0, 2}, on, got,
                         [&](std::span<const Dart> cells, std::vector<TearCandidate>& found) {
                           EXPECT_LE(cells.size(), kParallelBlock);
                           for (const Dart d : cells)
                             visit_edge(d, found);
                         });
      ASSERT_EQ(got.size(), expected.size() + 1) << threads << " threads";
      for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(got[i + 1].at, expected[i].at) << i;
        EXPECT_EQ(got[i + 1].measure, expected[i].measure) << i;
      }
    }
  }
  set_thread_count(0);
  EXPECT_EQ(collection.cells().rebuilds(), 1u);
}

/// Σ of an embedding over <o>(d) at one dart of each sub-orbit <e ∩ o>: the
/// definition of `sum E over <o>(d)`, walked by the map's own marked walk.
template <class T>
T sum_by_definition(const GMap& g, const Embedding<T>& e, Dart d, Orbit o) {
  const Orbit sub = Orbit::from_mask(static_cast<std::uint8_t>(e.orbit().mask() & o.mask()));
  T sum = generated::zero<T>();
  g.for_each_sub_orbit(d, o, sub, [&](Dart x) { sum = sum + e[x]; });
  return sum;
}

/// A 3D map with embeddings on every orbit (the single dart, those inside a
/// walked orbit, around it and across it), after random cuts.
GMap cut_block_with_embeddings(std::vector<Embedding<std::int64_t>>& columns) {
  GMap g = assemble_gmap(make_block(BlockKind::Hex, 3, 2, 2));
  std::mt19937 rng(3);
  cut_randomly(g, 6, rng);
  for (unsigned mask = 0; mask < 16; ++mask) {
    const Orbit on = Orbit::from_mask(static_cast<std::uint8_t>(mask));
    std::string name = "e";
    name += std::to_string(mask);
    auto e = g.add_embedding<std::int64_t>(name, on, MergePolicy::kKeepFirst, 0);
    g.for_each_cell(on, [&](Dart d) { e[d] = static_cast<std::int64_t>(rng() % 1000); });
    columns.push_back(e);
  }
  return g;
}

TEST(OrbitValues, EveryPairOfOrbitsSumsOneValuePerSubOrbit) {
  std::vector<Embedding<std::int64_t>> columns;
  const GMap g = cut_block_with_embeddings(columns);
  for (const auto& e : columns) {
    // Generated criteria fold through a reader (EmbeddingReader), other code
    // through the embedding: both sum the same values.
    const EmbeddingReader<std::int64_t> reader = e.reader();
    for (unsigned walk = 0; walk < 16; ++walk) {
      const Orbit o = Orbit::from_mask(static_cast<std::uint8_t>(walk));
      const Orbit sub = Orbit::from_mask(static_cast<std::uint8_t>(e.orbit().mask() & walk));
      for (Dart d = 0; d < g.capacity(); d += 5) {
        if (!g.is_alive(d)) continue;
        const std::int64_t expected = sum_by_definition(g, e, d, o);
        ASSERT_EQ(generated::fold_sum(g, e, d, o, sub), expected)
            << "embedding on " << e.orbit().str() << ", walk " << o.str() << ", dart " << d;
        ASSERT_EQ(generated::fold_sum(g, reader, d, o, sub), expected)
            << "reader of the embedding on " << e.orbit().str() << ", walk " << o.str() << ", dart "
            << d;
      }
    }
  }
}

TEST(SubOrbits, EveryPairOfOrbitsGivesTheDartsOfTheMarkedWalkInItsOrder) {
  // Whichever way generated::for_each_sub_orbit takes (one dart, a walk
  // without marks, slots of an attachment on <sub>, the marked walk), it
  // keeps the darts GMap::for_each_sub_orbit keeps, in the same order.
  std::vector<Embedding<std::int64_t>> columns;
  const GMap g = cut_block_with_embeddings(columns);
  for (unsigned walk = 0; walk < 16; ++walk) {
    const Orbit o = Orbit::from_mask(static_cast<std::uint8_t>(walk));
    for (unsigned inner = 0; inner < 16; ++inner) {
      const Orbit sub = Orbit::from_mask(static_cast<std::uint8_t>(inner));
      for (Dart d = 0; d < g.capacity(); d += 3) {
        if (!g.is_alive(d)) continue;
        std::vector<Dart> expected, got;
        g.for_each_sub_orbit(d, o, sub, [&](Dart x) { expected.push_back(x); });
        generated::for_each_sub_orbit(g, d, o, sub, [&](Dart x) { got.push_back(x); });
        ASSERT_EQ(got, expected) << "walk " << o.str() << ", sub-orbit " << sub.str() << ", dart "
                                 << d;
      }
    }
  }
}

TEST(SubOrbits, WalksWithoutMarksOnlyWhereTheyTouchNoStateOfTheMap) {
  // The walks criteria may run on every core: <o> a sub-orbit of itself, or
  // <sub> inside an <o> of at most two links.
  EXPECT_TRUE(generated::walks_without_marks(Orbit{0, 1}, Orbit{1}));
  EXPECT_TRUE(generated::walks_without_marks(Orbit{1, 2}, Orbit{}));
  EXPECT_TRUE(generated::walks_without_marks(Orbit{0, 1, 2}, Orbit{0, 1, 2, 3}));
  EXPECT_FALSE(generated::walks_without_marks(Orbit{1, 2}, Orbit{0, 1}));
  EXPECT_FALSE(generated::walks_without_marks(Orbit{0, 1, 2}, Orbit{1, 2}));
}

}  // namespace
}  // namespace rift
