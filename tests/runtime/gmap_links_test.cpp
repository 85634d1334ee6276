#include <gtest/gtest.h>

#include "rift/gmap/gmap.hpp"
#include "test_maps.hpp"

namespace rift {
namespace {

TEST(GMapLinks, NewDartIsFreeEverywhere) {
  GMap map(3);
  const Dart d = map.create_dart();
  for (int i = 0; i <= 3; ++i)
    EXPECT_TRUE(map.is_free(d, i));
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(map.size(), 1u);
}

TEST(GMapLinks, RejectsUnsupportedDimensions) {
  EXPECT_THROW(GMap(0), std::invalid_argument);
  EXPECT_THROW(GMap(4), std::invalid_argument);
}

TEST(GMapLinks, DeletedDartsAreRecycled) {
  GMap map(2);
  const Dart face = test::make_polygon(map, 3);
  EXPECT_EQ(map.size(), 6u);
  map.delete_dart(face);
  EXPECT_EQ(map.size(), 5u);
  EXPECT_FALSE(map.is_alive(face));
  EXPECT_TRUE(map.is_free(face + 1, 0));  // its 0-neighbour was unlinked
  EXPECT_TRUE(map.is_free(face + 5, 1));  // and its 1-neighbour
  EXPECT_TRUE(map.is_valid());
  const Dart again = map.create_dart();
  EXPECT_EQ(again, face);  // from the free list
  EXPECT_EQ(map.capacity(), 6u);
}

TEST(GMapValidity, DetectsAlpha0Alpha2Violation) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 3);
  // A raw 2-link on one dart only breaks alpha_0 o alpha_2.
  map.link(a, b, 2);
  const auto problems = map.check_validity();
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("alpha_0 o alpha_2"), std::string::npos) << problems.front();
  // Completing the sew along the edge restores validity.
  map.link(map.alpha(a, 0), map.alpha(b, 0), 2);
  EXPECT_TRUE(map.is_valid());
}

TEST(GMapValidity, DetectsEmbeddingNotSharedAlongOrbit) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 3);
  map.add_embedding<Vec3>("position", Orbit{1, 2});
  ASSERT_TRUE(map.is_valid());
  // Raw links join the two vertex orbits topologically but leave each with
  // its own value: the checker must see that the orbit disagrees.
  map.link(a, b, 2);
  map.link(map.alpha(a, 0), map.alpha(b, 0), 2);
  const auto problems = map.check_validity();
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("embedding on <1,2>"), std::string::npos) << problems.front();
}

TEST(GMapValidity, DetectsTwoOrbitsSharingASlot) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 3);
  map.add_embedding<Vec3>("position", Orbit{1, 2});
  OrbitAttachment& att = *map.attachment_of("position");
  // Vertex b (darts b and alpha_1(b)) moved into the slot of vertex a: each
  // orbit is constant and every count is right, but one slot holds two orbits.
  const Slot shared = att.slot(a);
  att.assign(b, shared);
  att.assign(map.alpha(b, 1), shared);
  const auto problems = map.check_validity();
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("two orbits share slot " + std::to_string(shared)),
            std::string::npos)
      << problems.front();
}

TEST(GMapValidity, DetectsADartOutsideItsOrbitsSlot) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 4);
  map.add_embedding<Real>("area", Orbit{0, 1});
  OrbitAttachment& att = *map.attachment_of("area");
  const Slot spare = att.allocate_slot();
  att.assign(a, spare);  // one dart of the face now elsewhere
  const auto problems = map.check_validity(20);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("hold different values"), std::string::npos) << problems.front();
}

TEST(GMapValidity, SewKeepsEmbeddingsShared) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 3);
  map.add_embedding<Vec3>("position", Orbit{1, 2});
  ASSERT_TRUE(map.sew(a, b, 2));
  EXPECT_TRUE(map.is_valid());
}

}  // namespace
}  // namespace rift
