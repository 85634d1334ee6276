#include <gtest/gtest.h>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/mesh/map_statistics.hpp"

namespace rift {
namespace {

TEST(Compaction, RenumbersDartsAndKeepsTopologyAndValues) {
  GMap map = assemble_gmap(make_grid(GridKind::Mix, 3, 3));
  auto pos = map.embedding<Vec3>("position");
  // Isolate and delete the first face.
  const Dart first = 0;
  std::vector<Dart> face;
  map.for_each_in_orbit(first, Orbit{0, 1}, [&](Dart d) { face.push_back(d); });
  for (Dart d : face) {
    if (!map.is_free(d, 2)) map.unsew(d, 2);
  }
  for (Dart d : face)
    map.delete_dart(d);
  ASSERT_TRUE(map.is_valid());
  const MapStatistics before = compute_statistics(map);
  Vec3 sum_before = Vec3::Zero();
  map.for_each_cell(Orbit{1, 2}, [&](Dart d) { sum_before += pos[d]; });

  const std::vector<Dart> new_index = map.compact();
  EXPECT_EQ(map.capacity(), map.size());
  EXPECT_EQ(new_index[face[0]], kNoDart);
  EXPECT_TRUE(map.is_valid());
  const MapStatistics after = compute_statistics(map);
  EXPECT_EQ(after.to_line(), before.to_line());
  Vec3 sum_after = Vec3::Zero();
  map.for_each_cell(Orbit{1, 2}, [&](Dart d) { sum_after += pos[d]; });
  EXPECT_TRUE(sum_after.isApprox(sum_before));
  // Slots are dense after compaction.
  EXPECT_EQ(pos.attachment().slot_capacity(), pos.attachment().live_slots());
}

// Values per dart (<>) live at the dart's own index (attachment.hpp, by
// dart): compaction moves each to its dart's new index, and a dart index
// taken again after a deletion starts from the default, not from the value
// its dead predecessor left.
TEST(Compaction, ValuesPerDartFollowTheirDarts) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 2));
  auto tag = map.add_embedding<Real>("tag", Orbit{}, MergePolicy::kKeepFirst, -1.0);
  ASSERT_TRUE(tag.attachment().by_dart());
  for (std::size_t k = 0; k < map.capacity(); ++k)
    tag[static_cast<Dart>(k)] = 100.0 + static_cast<Real>(k);
  std::vector<Dart> face;
  map.for_each_in_orbit(0, Orbit{0, 1}, [&](Dart d) { face.push_back(d); });
  for (Dart d : face) {
    if (!map.is_free(d, 2)) map.unsew(d, 2);
  }
  for (Dart d : face)
    map.delete_dart(d);
  ASSERT_TRUE(map.is_valid());
  EXPECT_EQ(tag.attachment().live_slots(), map.size());
  const std::size_t old_capacity = map.capacity();
  const std::vector<Dart> new_index = map.compact();
  ASSERT_TRUE(map.is_valid());
  EXPECT_EQ(tag.attachment().slot_capacity(), map.capacity());
  for (std::size_t old = 0; old < old_capacity; ++old) {
    if (new_index[old] == kNoDart) continue;
    EXPECT_EQ(tag[new_index[old]], 100.0 + static_cast<Real>(old)) << "dart " << old;
  }
  // A deleted dart's index taken again: its value is the default.
  const Dart gone = 5;
  for (int i = 0; i <= 2; ++i) {
    if (!map.is_free(gone, i)) map.unlink(gone, i);
  }
  map.delete_dart(gone);
  EXPECT_EQ(tag.attachment().slot(gone), kNoSlot);
  const Dart again = map.create_dart();
  ASSERT_EQ(again, gone);
  EXPECT_EQ(tag.attachment().slot(again), kNoSlot);
  map.assign_missing_slots(*map.attachment_of("tag"));
  EXPECT_EQ(tag[again], -1.0);
}

TEST(Compaction, RefusedWhileAMarkIsReserved) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 1, 1));
  const Mark m = map.reserve_mark();
  EXPECT_THROW(map.compact(), std::logic_error);
  map.free_mark(m);
  EXPECT_NO_THROW(map.compact());
}

}  // namespace
}  // namespace rift
