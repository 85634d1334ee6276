#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "rift/core/prefetch.hpp"
#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "test_maps.hpp"

namespace rift {
namespace {

std::set<Dart> orbit_set(const GMap& map, Dart d, Orbit o) {
  std::set<Dart> s;
  map.for_each_in_orbit(d, o, [&](Dart x) { EXPECT_TRUE(s.insert(x).second) << "visited twice"; });
  return s;
}

// Reference traversal: closure under the orbit's alphas with a std::set.
std::set<Dart> reference_orbit(const GMap& map, Dart d, Orbit o) {
  std::set<Dart> seen{d};
  std::vector<Dart> todo{d};
  while (!todo.empty()) {
    Dart x = todo.back();
    todo.pop_back();
    for (int i = 0; i <= map.dimension(); ++i) {
      if (o.contains(i) && seen.insert(map.alpha(x, i)).second) todo.push_back(map.alpha(x, i));
    }
  }
  return seen;
}

TEST(Marks, ReserveMarkUnmarkAndCount) {
  GMap map(2);
  test::make_polygon(map, 4);
  const Mark m = map.reserve_mark();
  EXPECT_EQ(map.reserved_marks(), 1);
  map.mark(0, m);
  map.mark(0, m);
  map.mark(3, m);
  EXPECT_EQ(map.marked_count(m), 2u);
  EXPECT_TRUE(map.is_marked(3, m));
  map.unmark(3, m);
  EXPECT_EQ(map.marked_count(m), 1u);
  const Mark m2 = map.reserve_mark();
  EXPECT_NE(m, m2);
  EXPECT_FALSE(map.is_marked(0, m2));
  map.free_mark(m);  // unmarks what is left
  map.free_mark(m2);
  EXPECT_EQ(map.reserved_marks(), 0);
  const Mark again = map.reserve_mark();
  EXPECT_FALSE(map.is_marked(0, again));
  map.free_mark(again);
}

TEST(Marks, RunningOutOfMarksThrows) {
  GMap map(2);
  std::vector<Mark> marks;
  for (int k = 0; k < GMap::kMaxMarks; ++k)
    marks.push_back(map.reserve_mark());
  EXPECT_THROW(map.reserve_mark(), std::runtime_error);
  for (Mark m : marks)
    map.free_mark(m);
}

TEST(Orbits, EveryOrbitTypeMatchesAReferenceTraversal) {
  for (const char* spec : {"grid:mix:3x2", "block:hex:2x2x1", "block:tet:2x1x1"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    const int n = map.dimension();
    for (int mask = 0; mask < (1 << (n + 1)); ++mask) {
      const Orbit o = Orbit::from_mask(static_cast<std::uint8_t>(mask));
      for (Dart d = 0; d < map.capacity(); d += 7) {
        EXPECT_EQ(orbit_set(map, d, o), reference_orbit(map, d, o)) << spec << " " << o.str();
      }
    }
    EXPECT_EQ(map.reserved_marks(), 0);
  }
}

TEST(Orbits, BoundaryTwoLinkOrbitIsAPath) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 4);
  // The vertex <1,2> of a lone face: 2 darts, both 2-free.
  EXPECT_EQ(map.orbit_size(a, Orbit{1, 2}), 2u);
  EXPECT_EQ(map.orbit_size(a, Orbit{0, 1}), 8u);
  EXPECT_EQ(map.orbit_size(a, Orbit{0}), 2u);
  EXPECT_EQ(map.orbit_size(a, Orbit{2}), 1u);
  EXPECT_TRUE(map.in_same_orbit(a, a + 5, Orbit{0, 1}));
  EXPECT_FALSE(map.in_same_orbit(a, a + 5, Orbit{0}));
}

TEST(Orbits, NestedTraversalsDoNotInterfere) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 3));
  std::size_t total = 0;
  map.for_each_in_orbit(0, Orbit{0, 1, 2}, [&](Dart d) {
    map.for_each_in_orbit(d, Orbit{0, 1, 2}, [&](Dart) { ++total; });
  });
  EXPECT_EQ(total, map.size() * map.size());
  EXPECT_EQ(map.reserved_marks(), 0);
}

// A vertex's faces (<0,1> sub-orbits of the vertex orbit <1,2>) reach past
// the vertex: each is visited once, from a dart of the vertex, and every
// mark is released with nothing left marked, call after call.
TEST(Orbits, SubOrbitsReachingOutsideTheOrbitAreVisitedOnceAndUnmarked) {
  GMap map = assemble_gmap(make_grid(GridKind::Tri, 4, 3));
  const Mark probe = map.reserve_mark();
  std::size_t visited = 0;
  map.for_each_cell(Orbit{1, 2}, [&](Dart v) {
    const std::set<Dart> vertex = reference_orbit(map, v, Orbit{1, 2});
    std::set<std::set<Dart>> expected;
    for (Dart x : vertex)
      expected.insert(reference_orbit(map, x, Orbit{0, 1}));
    std::set<std::set<Dart>> got;
    map.for_each_sub_orbit(v, Orbit{1, 2}, Orbit{0, 1}, [&](Dart f) {
      EXPECT_TRUE(vertex.count(f)) << "a dart outside the vertex";
      EXPECT_TRUE(got.insert(reference_orbit(map, f, Orbit{0, 1})).second) << "a face twice";
      map.mark(f, probe);
    });
    EXPECT_EQ(got, expected);
    visited += got.size();
  });
  // Three corners per triangle: each face is visited from each of its vertices.
  EXPECT_EQ(visited, 3 * map.count_cells_of_dimension(2));
  // Only the probe's marks remain: one per visit.
  EXPECT_EQ(map.marked_count(probe), visited);
  map.free_mark(probe);
  EXPECT_EQ(map.reserved_marks(), 0);
  for (Dart d = 0; d < map.size(); ++d) {
    for (Mark m = 0; m < GMap::kMaxMarks; ++m)
      ASSERT_FALSE(map.is_marked(d, m)) << "dart " << d << " mark " << m;
  }
}

// What for_each_cell promises, by its definition: the smallest dart of each
// orbit, in increasing order.
std::vector<Dart> smallest_darts_in_order(const GMap& map, Orbit o) {
  std::vector<Dart> out;
  map.for_each_dart([&](Dart d) {
    const std::set<Dart> orbit = reference_orbit(map, d, o);
    if (*orbit.begin() == d) out.push_back(d);
  });
  return out;
}

std::vector<Dart> cells_of(const GMap& map, Orbit o) {
  std::vector<Dart> out;
  map.for_each_cell(o, [&](Dart d) { out.push_back(d); });
  return out;
}

// Orbits with an embedding are passed over by their slots, the others by a
// marked walk: both give the same darts in the same order, also once unsews
// have split orbits (their new slots out of dart order).
TEST(Cells, ForEachCellGivesEachOrbitsSmallestDartInOrder) {
  for (const char* spec : {"grid:tri:5x4", "grid:mix:4x3", "block:hex:2x2x1", "block:tet:2x1x1"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    const int n = map.dimension();
    map.add_embedding<Real>("corner", Orbit::cell(0, n).without(n), MergePolicy::kSum, 1.0);
    map.add_embedding<Real>("edge", Orbit::cell(1, n), MergePolicy::kSum, 1.0);
    std::mt19937 rng(7);
    std::uniform_int_distribution<Dart> pick(0, static_cast<Dart>(map.capacity() - 1));
    for (int tear = 0; tear <= 12; ++tear) {
      for (const Orbit o :
           {Orbit::cell(0, n), Orbit::cell(1, n), Orbit::cell(n, n), Orbit::cell(0, n).without(n),
            Orbit::cell(n - 1, n), Orbit{0}, Orbit{}}) {
        ASSERT_EQ(cells_of(map, o), smallest_darts_in_order(map, o))
            << spec << " after " << tear << " unsews, orbit " << o.str();
      }
      const Dart d = pick(rng);
      if (!map.is_free(d, n)) map.unsew(d, n);
      ASSERT_TRUE(map.check_validity(3).empty()) << spec;
    }
  }
}

// Darts made one by one get their slots only when sewn or asked for: until
// then a pass over such an orbit walks the links.
TEST(Cells, ForEachCellOverDartsWithoutSlotsYet) {
  GMap map(2);
  map.add_embedding<Real>("value", Orbit{1, 2});
  const Dart a = map.create_dart();
  const Dart b = map.create_dart();
  const Dart c = map.create_dart();
  map.link(a, b, 1);
  EXPECT_EQ(cells_of(map, Orbit{1, 2}), (std::vector<Dart>{a, c}));
}

// slotted_attachment trusts the attachment's count of darts holding a slot
// instead of looking at every dart: that count must follow darts created
// without slots, deleted, given slots, unsewn and sewn again, and compaction.
TEST(Cells, SlottedAttachmentIsFoundExactlyWhenEveryLiveDartHasASlot) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 3));
  map.add_embedding<Real>("value", Orbit{1, 2}, MergePolicy::kSum, 1.0);
  OrbitAttachment* att = map.attachment_of("value");
  ASSERT_NE(att, nullptr);
  auto every_live_dart_slotted = [&] {
    bool all = true;
    map.for_each_dart([&](Dart d) { all = all && att->slot(d) != kNoSlot; });
    return all;
  };
  auto agree = [&](const char* when) {
    EXPECT_EQ(map.slotted_attachment(Orbit{1, 2}) != nullptr, every_live_dart_slotted()) << when;
  };
  agree("after assembly");
  EXPECT_NE(map.slotted_attachment(Orbit{1, 2}), nullptr);
  const Dart loose = map.create_dart();
  agree("after a dart made without a slot");
  EXPECT_EQ(map.slotted_attachment(Orbit{1, 2}), nullptr);
  map.delete_dart(loose);
  agree("after deleting it");
  EXPECT_NE(map.slotted_attachment(Orbit{1, 2}), nullptr);
  const Dart a = map.create_dart();
  map.create_dart();
  agree("after two more");
  map.assign_missing_slots(*att);
  agree("after giving them slots");
  EXPECT_NE(map.slotted_attachment(Orbit{1, 2}), nullptr);
  map.delete_dart(a);
  agree("after deleting a slotted dart");
  for (const auto& other : map.attachments())  // the map's own embeddings too
    map.assign_missing_slots(*other);
  std::mt19937 rng(11);
  std::uniform_int_distribution<Dart> pick(0, static_cast<Dart>(map.capacity() - 1));
  for (int k = 0; k < 20; ++k) {
    const Dart d = pick(rng);
    if (!map.is_alive(d) || map.is_free(d, 2)) continue;
    const Dart e = map.alpha(d, 2);
    map.unsew(d, 2);
    agree("after an unsew");
    if (k % 2 == 0) {
      ASSERT_TRUE(map.sew(d, e, 2));
      agree("after sewing it back");
    }
    const auto problems = map.check_validity(3);
    ASSERT_TRUE(problems.empty()) << problems.front();
  }
  map.compact();
  agree("after compaction");
  EXPECT_NE(map.slotted_attachment(Orbit{1, 2}), nullptr);
  EXPECT_TRUE(map.check_validity(3).empty());
}

TEST(Cells, ForEachCellGivesOneDartPerCell) {
  GMap map = assemble_gmap(make_grid(GridKind::Tri, 4, 3));
  std::set<std::set<Dart>> faces;
  std::size_t calls = 0;
  map.for_each_cell(Orbit{0, 1}, [&](Dart d) {
    ++calls;
    faces.insert(reference_orbit(map, d, Orbit{0, 1}));
  });
  EXPECT_EQ(calls, 24u);
  EXPECT_EQ(faces.size(), 24u);
  EXPECT_EQ(map.count_cells_of_dimension(2), 24u);
}

// prefetch_around is a hint: on a map large enough to be prefetched (2^19
// darts), asking for the lines around darts at every radius changes no link
// and no slot, leaves no mark reserved, and walks after it see the same map.
TEST(GMapPrefetch, AroundADartLeavesTheMapAsItWas) {
  GMap map = assemble_gmap(make_generated_mesh("grid:quad:256x256"));
  ASSERT_GE(map.capacity(), kPrefetchFromDarts);
  const Embedding<Vec3> position = map.embedding<Vec3>("position");
  std::vector<Dart> links;
  std::vector<Slot> slots;
  for (Dart d = 0; d < map.capacity(); ++d) {
    for (int i = 0; i <= 2; ++i)
      links.push_back(map.alpha(d, i));
    slots.push_back(position.slot(d));
  }
  const std::uint64_t version = map.topology_version();
  const std::size_t vertices = map.count_cells(Orbit{1, 2});
  for (const Dart d : {Dart{0}, Dart{777}, static_cast<Dart>(map.capacity() / 2),
                       static_cast<Dart>(map.capacity() - 1)}) {
    for (int radius = 0; radius <= 5; ++radius)
      map.prefetch_around(d, radius);
  }
  EXPECT_EQ(map.reserved_marks(), 0);
  EXPECT_EQ(map.topology_version(), version);
  std::size_t k = 0;
  for (Dart d = 0; d < map.capacity(); ++d) {
    for (int i = 0; i <= 2; ++i)
      ASSERT_EQ(map.alpha(d, i), links[k++]) << "dart " << d << " link " << i;
    ASSERT_EQ(position.slot(d), slots[d]) << "dart " << d;
  }
  EXPECT_EQ(map.count_cells(Orbit{1, 2}), vertices);
  EXPECT_TRUE(map.is_valid());
}

}  // namespace
}  // namespace rift
