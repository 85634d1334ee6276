#include <gtest/gtest.h>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "test_maps.hpp"

namespace rift {
namespace {

TEST(Sew, TwoSewLinksBothDartsOfTheEdge) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 4);
  EXPECT_EQ(map.count_cells_of_dimension(0), 7u);
  ASSERT_TRUE(map.sew(a, b, 2));
  EXPECT_EQ(map.alpha(a, 2), b);
  EXPECT_EQ(map.alpha(map.alpha(a, 0), 2), map.alpha(b, 0));  // the whole orbit <0>
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(map.count_cells_of_dimension(0), 5u);
  EXPECT_EQ(map.count_cells_of_dimension(1), 6u);
  EXPECT_EQ(map.count_cells_of_dimension(2), 2u);
}

TEST(Sew, RefusesDartsAlreadySewnOrIdentical) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 3);
  const Dart c = test::make_polygon(map, 3);
  EXPECT_FALSE(map.sew(a, a, 2));
  ASSERT_TRUE(map.sew(a, b, 2));
  EXPECT_NE(map.why_not_sewable(a, c, 2).find("already 2-sewn"), std::string::npos);
  EXPECT_FALSE(map.sew(a, c, 2));
  EXPECT_FALSE(map.sew(a, c, 5));
  EXPECT_TRUE(map.is_valid());
}

TEST(Sew, ThreeSewNeedsIsomorphicFaces) {
  GMap map(3);
  MeshData tet;
  tet.dimension = 3;
  tet.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tet.add_element(ElementType::Tetra, {0, 1, 2, 3});
  GMap t = assemble_gmap(tet);
  MeshData hex = make_block(BlockKind::Hex, 1, 1, 1);
  GMap h = assemble_gmap(hex);
  // Build both in one map by sewing within one map: use two tetrahedra and a hexahedron.
  MeshData mixed;
  mixed.dimension = 3;
  mixed.points = hex.points;
  mixed.points.push_back(Vec3(2, 0, 0));
  mixed.points.push_back(Vec3(2, 1, 0));
  mixed.points.push_back(Vec3(2, 0, 1));
  mixed.add_element(ElementType::Hexa, {0, 1, 3, 2, 4, 5, 7, 6});
  mixed.add_element(ElementType::Tetra, {8, 9, 10, 1});
  GMap m = assemble_gmap(mixed);
  // Dart 0 belongs to a quad face of the hexahedron, the last darts to a
  // triangle of the tetrahedron: not isomorphic.
  const Dart hex_dart = 0;
  const Dart tet_dart = static_cast<Dart>(m.capacity() - 1);
  EXPECT_NE(m.why_not_sewable(hex_dart, tet_dart, 3).find("not isomorphic"), std::string::npos);
  EXPECT_FALSE(m.sew(hex_dart, tet_dart, 3));
  EXPECT_TRUE(m.is_valid());
  (void)t;
  (void)h;
}

TEST(Sew, TwoTetrahedraShareAFaceAfterThreeSew) {
  MeshData mesh;
  mesh.dimension = 3;
  mesh.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  mesh.add_element(ElementType::Tetra, {0, 1, 2, 3});
  mesh.add_element(ElementType::Tetra, {1, 2, 3, 4});
  GMap map = assemble_gmap(mesh);
  EXPECT_EQ(map.count_cells_of_dimension(2), 7u);
  EXPECT_EQ(map.count_cells_of_dimension(0), 5u);
  // Find a 3-sewn dart, unsew its face and sew it back.
  Dart sewn = kNoDart;
  map.for_each_dart([&](Dart d) {
    if (sewn == kNoDart && !map.is_free(d, 3)) sewn = d;
  });
  ASSERT_NE(sewn, kNoDart);
  const Dart partner = map.alpha(sewn, 3);
  map.unsew(sewn, 3);
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(map.count_cells_of_dimension(2), 8u);
  EXPECT_EQ(map.count_cells_of_dimension(0), 8u);  // the face's 3 vertices split
  EXPECT_EQ(map.count_cells(Orbit::all(3)), 2u);
  ASSERT_TRUE(map.sew(sewn, partner, 3));
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(map.count_cells_of_dimension(0), 5u);
  EXPECT_EQ(map.count_cells(Orbit::all(3)), 1u);
}

TEST(Unsew, SplittingAnEdgeOfTheQuadGrid) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 2, 1));
  ASSERT_EQ(map.count_cells_of_dimension(0), 6u);
  Dart inner = kNoDart;
  map.for_each_dart([&](Dart d) {
    if (inner == kNoDart && !map.is_free(d, 2)) inner = d;
  });
  map.unsew(inner, 2);
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(map.count_cells_of_dimension(0), 8u);
  EXPECT_EQ(map.count_cells_of_dimension(1), 8u);
  EXPECT_EQ(map.count_cells(Orbit::all(2)), 2u);
  map.unsew(inner, 2);  // already free: nothing happens
  EXPECT_EQ(map.count_cells_of_dimension(1), 8u);
}

}  // namespace
}  // namespace rift
