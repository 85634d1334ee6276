// Non-manifold input gives a valid G-map: a point whose elements form two
// separate fans is two vertex orbits, and an edge or face shared by more than
// two elements is sewn between the first two only (see assemble.hpp).
#include <gtest/gtest.h>

#include "io_test_support.hpp"

namespace rift::test {
namespace {

TEST(NonManifold, TwoTrianglesTouchingAtOnePointGiveTwoVertexOrbitsThere) {
  // A bow tie: triangles 1 2 3 and 3 4 5 share point 3 only. Nothing is sewn,
  // so each triangle is its own component and point 3 is two orbits: 6 in all.
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 1 0\nv 2 2 0\n"
      "f 1 2 3\nf 3 4 5\n";
  AssemblyReport report;
  EXPECT_EQ(read_counts(write_temp("bowtie.obj", text), &report), (Counts{12, 6, 6, 2, 0, 2, 6}));
  EXPECT_EQ(report.nonmanifold_shared, 0u);
}

TEST(NonManifold, ThreeTrianglesOnOneEdgeGiveAValidMap) {
  // Triangles 1 2 3, 1 2 4 and 1 2 5 share edge 1 2. The first two are sewn
  // there; the third keeps its copy of the edge free: edge 1 2 is two orbits
  // (8 edges), and points 1 and 2 are two orbits each (the sewn fan and the
  // lone triangle): 3 + 2 * 2 = 7 vertices. Boundary: 2 + 2 + 3 edges.
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0\nv 0.5 0 1\n"
      "f 1 2 3\nf 1 2 4\nf 1 2 5\n";
  AssemblyReport report;
  EXPECT_EQ(read_counts(write_temp("fin.obj", text), &report), (Counts{18, 7, 8, 3, 0, 2, 7}));
  EXPECT_EQ(report.nonmanifold_shared, 1u);
}

TEST(NonManifold, TwoTetrahedraTouchingAlongAnEdgeOnly) {
  // Tetrahedra 1 2 3 4 and 1 2 5 6 share edge 1 2 and no face: nothing is
  // sewn, so they stay two components with 4 faces each.
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n"
      "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 -1 0\n6 0 0 -1\n$EndNodes\n"
      "$Elements\n2\n1 4 0 1 2 3 4\n2 4 0 1 2 5 6\n$EndElements\n";
  EXPECT_EQ(read_counts(write_temp("edge_touch.msh", text)), (Counts{48, 8, 12, 8, 2, 2, 8}));
}

TEST(NonManifold, ThreeTetrahedraOnOneFaceGiveAValidMap) {
  // Tetrahedra on face 1 2 3 with apexes 4, 5 and 6 (the third overlaps the
  // first, as a broken mesh might).
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n"
      "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n6 0.1 0.1 2\n$EndNodes\n"
      "$Elements\n3\n1 4 0 1 2 3 4\n2 4 0 1 3 2 5\n3 4 0 1 2 3 6\n$EndElements\n";
  AssemblyReport report;
  const MeshData mesh = read_mesh_file(write_temp("three_on_face.msh", text));
  const GMap map = assemble_gmap(mesh, &report);
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
  EXPECT_EQ(report.nonmanifold_shared, 1u);
  EXPECT_EQ(compute_statistics(map).volumes, 3u);
}

TEST(NonManifold, InvertedTetrahedraAreReorientedAndCounted) {
  // The second tetrahedron is listed with negative orientation.
  const std::string text =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n"
      "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 -1 0\n"
      "Tetrahedra\n2\n1 2 3 4 0\n1 2 3 5 0\nEnd\n";
  AssemblyReport report;
  EXPECT_EQ(read_counts(write_temp("inverted.mesh", text), &report),
            (Counts{48, 5, 9, 7, 2, 1, 6}));
  EXPECT_EQ(report.reoriented_solids, 1u);
}

}  // namespace
}  // namespace rift::test
