#include <gtest/gtest.h>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "test_maps.hpp"

namespace rift {
namespace {

struct TwoTriangles {
  GMap map{2};
  Dart a = test::make_polygon(map, 3);
  Dart b = test::make_polygon(map, 3);
};

TEST(Embedding, EveryDartOfAnOrbitReadsTheSameValue) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 2, 2));
  auto pos = map.embedding<Vec3>("position");
  ASSERT_TRUE(pos);
  map.for_each_dart([&](Dart d) {
    map.for_each_in_orbit(d, Orbit{1, 2}, [&](Dart x) { EXPECT_EQ(pos[x], pos[d]); });
  });
  // Writing through one dart is seen from every dart of the vertex.
  pos[0] = Vec3(7, 8, 9);
  map.for_each_in_orbit(0, Orbit{1, 2}, [&](Dart x) { EXPECT_EQ(pos[x], Vec3(7, 8, 9)); });
  EXPECT_TRUE(map.is_valid());
}

TEST(Embedding, AllValueTypesAndDefaults) {
  GMap map(2);
  test::make_polygon(map, 4);
  auto r = map.add_embedding<Real>("r", Orbit{0}, MergePolicy::kSum, 1.5);
  auto i = map.add_embedding<std::int64_t>("i", Orbit{0, 1}, MergePolicy::kKeepFirst, 3);
  auto b = map.add_embedding<Bool>("b", Orbit{}, MergePolicy::kKeepFirst, true);
  auto m = map.add_embedding<Mat3>("m", Orbit{1}, MergePolicy::kMean, Mat3::Identity());
  EXPECT_EQ(r[0], 1.5);
  EXPECT_EQ(i[5], 3);
  EXPECT_TRUE(b[2]);
  EXPECT_EQ(m[1], Mat3::Identity());
  EXPECT_EQ(r.attachment().live_slots(), 4u);  // four half-edges <0>
  EXPECT_EQ(i.attachment().live_slots(), 1u);  // one face
  EXPECT_EQ(b.attachment().live_slots(), 8u);  // one per dart
  EXPECT_THROW(map.add_embedding<Real>("r", Orbit{0}), std::invalid_argument);
  EXPECT_THROW(map.add_embedding<Real>("z", Orbit{3}), std::invalid_argument);
  EXPECT_THROW(map.embedding<Vec3>("r"), std::invalid_argument);
  EXPECT_FALSE(map.embedding<Real>("missing"));
  EXPECT_TRUE(map.is_valid());
}

TEST(Embedding, SewMergesWithEachPolicy) {
  TwoTriangles t;
  auto keep = t.map.add_embedding<Real>("keep", Orbit{1, 2}, MergePolicy::kKeepFirst);
  auto sum = t.map.add_embedding<Real>("sum", Orbit{1, 2}, MergePolicy::kSum);
  auto mean = t.map.add_embedding<Vec3>("mean", Orbit{1, 2}, MergePolicy::kMean);
  keep[t.a] = 1;
  keep[t.b] = 2;
  sum[t.a] = 1;
  sum[t.b] = 2;
  mean[t.a] = Vec3(0, 0, 0);
  mean[t.b] = Vec3(2, 4, 6);
  ASSERT_TRUE(t.map.sew(t.a, t.b, 2));
  EXPECT_EQ(keep[t.a], 1);
  EXPECT_EQ(keep[t.b], 1);
  EXPECT_EQ(sum[t.b], 3);
  EXPECT_EQ(mean[t.b], Vec3(1, 2, 3));
  EXPECT_TRUE(t.map.is_valid());
}

TEST(Embedding, RefusePolicyVetoesDifferentValues) {
  TwoTriangles t;
  auto tag = t.map.add_embedding<std::int64_t>("tag", Orbit{1, 2}, MergePolicy::kRefuse);
  tag[t.a] = 1;
  tag[t.b] = 2;
  EXPECT_NE(t.map.why_not_sewable(t.a, t.b, 2).find("'tag' refuses"), std::string::npos);
  EXPECT_FALSE(t.map.sew(t.a, t.b, 2));
  EXPECT_TRUE(t.map.is_free(t.a, 2));
  // Equal values on both vertices of the edge: the sew goes through.
  tag[t.b] = 1;
  tag[t.map.alpha(t.b, 0)] = tag[t.map.alpha(t.a, 0)];
  EXPECT_TRUE(t.map.sew(t.a, t.b, 2));
  EXPECT_TRUE(t.map.is_valid());
}

TEST(Embedding, UnsewGivesEachPartACopy) {
  TwoTriangles t;
  auto pos = t.map.add_embedding<Vec3>("position", Orbit{1, 2}, MergePolicy::kMean);
  auto face_id = t.map.add_embedding<std::int64_t>("face", Orbit{0, 1});
  ASSERT_TRUE(t.map.sew(t.a, t.b, 2));
  pos[t.a] = Vec3(1, 2, 3);
  const std::size_t slots_before = pos.attachment().live_slots();
  t.map.unsew(t.a, 2);
  EXPECT_TRUE(t.map.is_valid());
  EXPECT_EQ(pos.attachment().live_slots(), slots_before + 2);  // two vertices split
  EXPECT_EQ(pos[t.a], Vec3(1, 2, 3));
  EXPECT_EQ(pos[t.b], Vec3(1, 2, 3));
  EXPECT_NE(pos.slot(t.a), pos.slot(t.b));
  pos[t.b] = Vec3(0, 0, 0);  // the copies are independent
  EXPECT_EQ(pos[t.a], Vec3(1, 2, 3));
  EXPECT_EQ(face_id.attachment().live_slots(), 2u);  // faces are not touched
}

TEST(Embedding, UnsewThatDoesNotDisconnectKeepsOneValue) {
  // In a closed fan (interior vertex of a grid), unsewing one edge does not
  // split the vertex at the fan's other side.
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 2, 2));
  auto pos = map.embedding<Vec3>("position");
  const std::size_t vertices = pos.attachment().live_slots();
  Dart centre = kNoDart;
  map.for_each_dart([&](Dart d) {
    if (centre == kNoDart && pos[d] == Vec3(0.5, 0.5, 0) && !map.is_free(d, 2)) centre = d;
  });
  ASSERT_NE(centre, kNoDart);
  map.unsew(centre, 2);
  EXPECT_TRUE(map.is_valid());
  // The centre stays one vertex (its fan is still connected the other way
  // round); only the edge's boundary extremity splits.
  EXPECT_EQ(pos.attachment().live_slots(), vertices + 1);
  EXPECT_EQ(map.count_cells_of_dimension(0), vertices + 1);
}

TEST(Embedding, DeletingDartsFreesSlots) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  auto face = map.add_embedding<Real>("area", Orbit{0, 1});
  EXPECT_EQ(face.attachment().live_slots(), 1u);
  for (Dart d = a; d < a + 6; ++d)
    map.delete_dart(d);
  EXPECT_EQ(face.attachment().live_slots(), 0u);
  EXPECT_TRUE(map.is_valid());
}

}  // namespace
}  // namespace rift
