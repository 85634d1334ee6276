#include <gtest/gtest.h>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "test_maps.hpp"

namespace rift {
namespace {

/// The first dart sewn along dimension 2 (an interior edge to tear), or kNoDart.
Dart first_sewn_dart(const GMap& map) {
  Dart inner = kNoDart;
  map.for_each_dart([&](Dart d) {
    if (inner == kNoDart && !map.is_free(d, 2)) inner = d;
  });
  return inner;
}

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

// Declared embeddings hold no storage until first asked for (issue 12, lean
// memory); until then every slot reads as the default, through sews, unsews,
// new darts and compaction, and asking gives a column of the right size.
TEST(Embedding, DeclaredColumnsGetStorageOnlyWhenAskedFor) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 3));
  map.declare_embedding<Vec3>("force", Orbit{}, MergePolicy::kKeepFirst, Vec3(1, 2, 3));
  map.declare_embedding<Real>("k", Orbit{0}, MergePolicy::kSum, 0.0);
  const ColumnBase* force = map.find_column("force");
  const ColumnBase* k = map.find_column("k");
  ASSERT_TRUE(force && k);
  EXPECT_FALSE(force->allocated());
  EXPECT_FALSE(k->allocated());
  EXPECT_EQ(std::get<Vec3>(force->get(5)), Vec3(1, 2, 3));
  // Tearing an interior edge (unsew) and adding darts: still no storage.
  const Dart inner = first_sewn_dart(map);
  ASSERT_NE(inner, kNoDart);
  map.unsew(inner, 2);
  const Dart fresh = map.create_darts(4);
  map.link(fresh, fresh + 1, 0);
  map.link(fresh + 2, fresh + 3, 0);
  for (const auto& attachment : map.attachments())
    map.assign_missing_slots(*attachment);
  EXPECT_FALSE(force->allocated());
  EXPECT_FALSE(k->allocated());
  EXPECT_TRUE(map.is_valid());
  // Asking allocates every slot, new darts included, holding the default.
  Embedding<Vec3> f = map.embedding<Vec3>("force");
  EXPECT_TRUE(force->allocated());
  EXPECT_EQ(f.values().size(), f.attachment().slot_capacity());
  map.for_each_dart([&](Dart d) { EXPECT_EQ(f[d], Vec3(1, 2, 3)) << d; });
  // Once allocated, a column grows with the darts a rewrite creates.
  const Dart more = map.create_darts(2);
  for (const auto& attachment : map.attachments())
    map.assign_missing_slots(*attachment);
  f[more + 1] = Vec3(4, 5, 6);
  EXPECT_EQ(f[more], Vec3(1, 2, 3));
  EXPECT_EQ(f[more + 1], Vec3(4, 5, 6));
  EXPECT_GE(f.values().size(), f.attachment().slot_capacity());
  // Compaction keeps an unallocated column unallocated and sized right for later.
  map.compact();
  EXPECT_FALSE(k->allocated());
  Embedding<Real> kk = map.embedding<Real>("k");
  EXPECT_EQ(kk.values().size(), kk.attachment().slot_capacity());
  EXPECT_EQ(kk[0], 0.0);
  EXPECT_TRUE(map.is_valid());
}

// An attachment keeps no slots until one of its columns is asked for
// (attachment.hpp: dormant, issue 12, lean memory). Tears, new darts,
// deleted darts and compaction pass it by; once woken it holds one slot per
// orbit of the map as it is then, every value the default, and from then on
// follows the topology like any other attachment.
TEST(Embedding, AnAttachmentKeepsNoSlotsUntilAColumnIsAskedFor) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 3));
  map.declare_embedding<Real>("wing", Orbit{0, 2}, MergePolicy::kKeepFirst, 2.5);
  map.declare_embedding<Real>("wing_sum", Orbit{0, 2}, MergePolicy::kSum, 0.0);
  OrbitAttachment* att = map.attachment_of("wing");
  ASSERT_NE(att, nullptr);
  EXPECT_TRUE(att->dormant());
  EXPECT_EQ(att->slot_capacity(), 0u);
  // Tear two interior edges, add and delete darts, compact: nothing to keep.
  for (int tear = 0; tear < 2; ++tear) {
    const Dart inner = first_sewn_dart(map);
    ASSERT_NE(inner, kNoDart);
    map.unsew(inner, 2);
  }
  const Dart fresh = map.create_darts(6);
  map.link(fresh, fresh + 1, 0);
  map.link(fresh + 2, fresh + 3, 0);
  map.delete_dart(fresh + 5);
  for (const auto& attachment : map.attachments())
    map.assign_missing_slots(*attachment);
  EXPECT_TRUE(att->dormant());
  EXPECT_TRUE(map.is_valid());
  map.compact();
  EXPECT_TRUE(att->dormant());
  // Asking for a column wakes the attachment: one slot per <0,2> orbit.
  Embedding<Real> wing = map.embedding<Real>("wing");
  EXPECT_FALSE(att->dormant());
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
  EXPECT_EQ(att->live_slots(), map.count_cells(Orbit{0, 2}));
  map.for_each_dart([&](Dart d) { EXPECT_EQ(wing[d], 2.5) << d; });
  // Awake, it follows a tear: the two halves of a torn <0,2> orbit (the
  // darts of an edge on both sides) each keep the value.
  const Dart inner = first_sewn_dart(map);
  ASSERT_NE(inner, kNoDart);
  const Dart other = map.alpha(inner, 2);
  wing[inner] = 7.0;
  EXPECT_EQ(wing[other], 7.0);
  map.unsew(inner, 2);
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
  EXPECT_NE(wing.slot(inner), wing.slot(other));
  EXPECT_EQ(wing[inner], 7.0);
  EXPECT_EQ(wing[other], 7.0);
  EXPECT_EQ(att->live_slots(), map.count_cells(Orbit{0, 2}));
  // Sewing back merges the two slots again.
  ASSERT_TRUE(map.sew(inner, other, 2));
  EXPECT_EQ(wing.slot(inner), wing.slot(other));
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
  // The other column of the attachment shares its slots.
  Embedding<Real> sum = map.embedding<Real>("wing_sum");
  EXPECT_EQ(sum.slot(inner), wing.slot(inner));
}

// A sum of two non-zero defaults is not the default: such a merge needs
// storage, and gets it; a zero default or a mean merges to itself without it.
TEST(Embedding, UnallocatedColumnsMergeLikeAllocatedOnes) {
  TwoTriangles t;
  t.map.declare_embedding<Real>("sum_one", Orbit{1, 2}, MergePolicy::kSum, 1.0);
  t.map.declare_embedding<Real>("sum_zero", Orbit{1, 2}, MergePolicy::kSum, 0.0);
  t.map.declare_embedding<Real>("mean_two", Orbit{1, 2}, MergePolicy::kMean, 2.0);
  ASSERT_TRUE(t.map.sew(t.a, t.b, 2));
  EXPECT_TRUE(t.map.find_column("sum_one")->allocated());
  EXPECT_FALSE(t.map.find_column("sum_zero")->allocated());
  EXPECT_FALSE(t.map.find_column("mean_two")->allocated());
  EXPECT_EQ(t.map.embedding<Real>("sum_one")[t.a], 2.0);
  const Dart apex = t.map.alpha(t.map.alpha(t.map.alpha(t.a, 0), 1), 0);
  EXPECT_EQ(t.map.embedding<Real>("sum_one")[apex], 1.0);  // a vertex the sew left alone
  EXPECT_EQ(t.map.embedding<Real>("mean_two")[t.a], 2.0);
  // Setting a value through the type-erased face allocates only when it differs.
  ColumnBase* zero = t.map.find_column("sum_zero");
  zero->set(0, Real(0));
  EXPECT_FALSE(zero->allocated());
  zero->set(0, Real(5));
  EXPECT_TRUE(zero->allocated());
  EXPECT_EQ(std::get<Real>(zero->get(0)), 5.0);
  EXPECT_TRUE(t.map.is_valid());
}

// A withheld column (GMap::withhold_storage: stored forces nothing reads)
// is handed out without storage: const reads give the default, tears cost it
// nothing, and its first mutable use allocates it, holding the default.
TEST(Embedding, WithheldColumnsGetStorageAtTheirFirstMutableUse) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 3));
  map.declare_embedding<Vec3>("force", Orbit{}, MergePolicy::kKeepFirst, Vec3(1, 2, 3));
  EXPECT_FALSE(map.withhold_storage("no_such_column"));
  ASSERT_TRUE(map.withhold_storage("force"));
  const ColumnBase* column = map.find_column("force");
  Embedding<Vec3> f = map.embedding<Vec3>("force");
  ASSERT_TRUE(f);
  EXPECT_FALSE(column->allocated());
  const Embedding<Vec3>& read = f;
  map.for_each_dart([&](Dart d) { EXPECT_EQ(read[d], Vec3(1, 2, 3)) << d; });
  EXPECT_EQ(f.slot(7), f.attachment().slot(7));
  const Dart inner = first_sewn_dart(map);
  ASSERT_NE(inner, kNoDart);
  map.unsew(inner, 2);
  EXPECT_FALSE(column->allocated());
  EXPECT_TRUE(map.is_valid());
  f[inner] = Vec3(4, 5, 6);  // a write allocates
  EXPECT_TRUE(column->allocated());
  EXPECT_EQ(f.values().size(), f.attachment().slot_capacity());
  EXPECT_EQ(read[inner], Vec3(4, 5, 6));
  EXPECT_EQ(read[map.alpha(inner, 0)], Vec3(1, 2, 3));
  // An allocated column cannot be withheld any more.
  EXPECT_FALSE(map.withhold_storage("force"));
}

// A criterion's collect reads through EmbeddingReaders taken once: each
// reads what the embedding reads, at every dart, from a column with storage
// and from a withheld one (its default, never allocating it).
TEST(Embedding, ReadersReadWhatTheEmbeddingReads) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 3, 2));
  map.declare_embedding<Real>("edge_value", Orbit{0}, MergePolicy::kKeepFirst, -1.0);
  map.declare_embedding<Vec3>("held", Orbit{}, MergePolicy::kKeepFirst, Vec3(1, 2, 3));
  ASSERT_TRUE(map.withhold_storage("held"));
  Embedding<Vec3> pos = map.embedding<Vec3>("position");
  Embedding<Real> edge = map.embedding<Real>("edge_value");
  Embedding<Vec3> held = map.embedding<Vec3>("held");
  map.for_each_dart([&](Dart d) { edge[d] = static_cast<Real>(edge.slot(d)) + 0.5; });
  const EmbeddingReader<Vec3> pos_reader = pos.reader();
  const EmbeddingReader<Real> edge_reader = edge.reader();
  const EmbeddingReader<Vec3> held_reader = held.reader();
  int darts = 0;
  map.for_each_dart([&](Dart d) {
    ++darts;
    EXPECT_EQ(pos_reader[d], pos[d]) << d;
    EXPECT_EQ(&pos_reader[d], &pos.values()[pos.slot(d)]) << d;
    EXPECT_EQ(edge_reader[d], static_cast<Real>(edge.slot(d)) + 0.5) << d;
    EXPECT_EQ(edge_reader.slot(d), edge.slot(d)) << d;
    EXPECT_EQ(held_reader[d], Vec3(1, 2, 3)) << d;
  });
  EXPECT_EQ(darts, 3 * 2 * 8);
  EXPECT_FALSE(map.find_column("held")->allocated());
}

}  // namespace
}  // namespace rift
