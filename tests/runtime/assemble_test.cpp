#include <gtest/gtest.h>

#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/mesh/map_statistics.hpp"
#include "rift/mesh/mesh_error.hpp"

namespace rift {
namespace {

MeshData triangles(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> tris) {
  MeshData m;
  m.dimension = 2;
  m.source = "test.obj";
  m.points = std::move(points);
  int line = 1;
  for (auto& t : tris)
    m.add_element(ElementType::Polygon, t.begin(), t.end(), line++);
  return m;
}

TEST(Assemble, BowTieVertexIsTwoVertexOrbits) {
  // Two triangles touching only at point 0: two separate fans.
  auto m = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)},
                     {{0, 1, 2}, {0, 3, 4}});
  GMap map = assemble_gmap(m);
  EXPECT_TRUE(map.is_valid());
  const MapStatistics s = compute_statistics(map);
  EXPECT_EQ(s.vertices, 6u);  // point 0 counts twice
  EXPECT_EQ(s.components, 2u);
}

TEST(Assemble, EdgeSharedByThreeTrianglesStaysValid) {
  auto m = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)},
                     {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}});
  AssemblyReport report;
  GMap map = assemble_gmap(m, &report);
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(report.nonmanifold_shared, 1u);
  const MapStatistics s = compute_statistics(map);
  EXPECT_EQ(s.faces, 3u);
  EXPECT_EQ(s.edges, 8u);  // the shared edge exists twice: once sewn, once free
}

TEST(Assemble, OppositeOrientationsAreSewnAnyway) {
  // G-maps are not oriented: a flipped neighbour is still sewn.
  auto m = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
                     {{0, 1, 2}, {0, 2, 3}});
  auto flipped = triangles(m.points, {{0, 1, 2}, {0, 3, 2}});
  for (const MeshData& mesh : {m, flipped}) {
    GMap map = assemble_gmap(mesh);
    EXPECT_TRUE(map.is_valid());
    EXPECT_EQ(compute_statistics(map).edges, 5u);
  }
}

TEST(Assemble, PositionsAndPointIndicesLandOnVertices) {
  auto m = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(9, 9, 9)}, {{0, 1, 2}});
  AssemblyReport report;
  GMap map = assemble_gmap(m, &report);
  auto pos = map.embedding<Vec3>("position");
  auto idx = map.embedding<std::int64_t>("point_index");
  map.for_each_dart([&](Dart d) { EXPECT_EQ(pos[d], m.points[static_cast<std::size_t>(idx[d])]); });
  EXPECT_EQ(report.unused_points, 1u);
}

TEST(Assemble, InvertedTetrahedronIsReoriented) {
  MeshData m;
  m.dimension = 3;
  m.source = "t.msh";
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.add_element(ElementType::Tetra, {0, 2, 1, 3}, 7);
  AssemblyReport report;
  GMap map = assemble_gmap(m, &report);
  EXPECT_EQ(report.reoriented_solids, 1u);
  EXPECT_TRUE(map.is_valid());
  EXPECT_EQ(compute_statistics(map).faces, 4u);
}

// The assembly numbers its elements by their runs of darts
// (GMap::number_orbits_by_runs) instead of walking them: the slots must be the
// walk's, slot k on the orbit whose smallest dart comes k-th, and element k.
TEST(Assemble, ElementsNumberedByTheirDartsAsAWalkWouldNumberThem) {
  MeshData mixed = make_grid(GridKind::Mix, 5, 4);
  MeshData hex = make_block(BlockKind::Hex, 3, 2, 2);
  MeshData tet = make_block(BlockKind::Tet, 2, 2, 1);
  // A bow tie: elements of one point in two fans, and a lone element.
  MeshData bow = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0),
                            Vec3(-1, -1, 0), Vec3(5, 5, 0), Vec3(6, 5, 0), Vec3(5, 6, 0)},
                           {{0, 1, 2}, {0, 3, 4}, {5, 6, 7}});
  for (const MeshData* mesh : {&mixed, &hex, &tet, &bow}) {
    GMap map = assemble_gmap(*mesh);
    ASSERT_TRUE(map.is_valid()) << map.check_validity().front();
    const Orbit element = Orbit::all(mesh->dimension - 1);
    const Embedding<std::int64_t> index = map.embedding<std::int64_t>("element_index");
    ASSERT_EQ(index.attachment().orbit(), element);
    Slot expected = 0;
    map.for_each_cell(element, [&](Dart d) {
      map.for_each_in_orbit(d, element, [&](Dart x) {
        EXPECT_EQ(index.slot(x), expected) << "dart " << x;
        EXPECT_EQ(index[x], std::int64_t{expected});
      });
      ++expected;
    });
    EXPECT_EQ(expected, mesh->elements.size());
    EXPECT_EQ(index.attachment().live_slots(), mesh->elements.size());
  }
}

TEST(Assemble, RunsAreRefusedWhereTheOrbitHasSlotsOrTheyMissDarts) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 2, 1));
  const std::vector<Dart> starts = {0, 8};
  EXPECT_THROW(map.number_orbits_by_runs(Orbit{0, 1}, starts), std::logic_error);  // numbered
  GMap bare(2);
  bare.create_darts(16);
  // Darts 0 to 3 in no run; runs out of order.
  EXPECT_THROW(bare.number_orbits_by_runs(Orbit{0, 1}, std::vector<Dart>{4}), std::logic_error);
  EXPECT_THROW(bare.number_orbits_by_runs(Orbit{1}, std::vector<Dart>{8, 0}), std::logic_error);
}

std::string error_of(const MeshData& m) {
  try {
    assemble_gmap(m);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Assemble, BadElementsNameFileAndLine) {
  auto out_of_range =
      triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, {{0, 1, 2}, {0, 1, 7}});
  EXPECT_EQ(
      error_of(out_of_range),
      "test.obj:2: error: polygon (element 2) refers to vertex 8 but the mesh has 3 vertices");
  auto repeated = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, {{0, 1, 1}});
  EXPECT_EQ(error_of(repeated), "test.obj:1: error: polygon (element 1) repeats vertex 2");
  MeshData empty;
  empty.source = "empty.obj";
  EXPECT_EQ(error_of(empty), "empty.obj: error: the mesh has no element");
  auto nan = triangles({Vec3(0, 0, 0), Vec3(1, 0, NAN), Vec3(1, 1, 0)}, {{0, 1, 2}});
  EXPECT_NE(error_of(nan).find("vertex 2 has a non-finite coordinate"), std::string::npos);
  MeshData wrong_dim = triangles({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, {{0, 1, 2}});
  wrong_dim.dimension = 3;
  EXPECT_NE(error_of(wrong_dim).find("does not belong in a 3D mesh"), std::string::npos);
}

}  // namespace
}  // namespace rift
