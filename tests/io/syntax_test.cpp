// Format features the shape writers do not produce: OBJ corner forms and
// negative indices, Gmsh sections and parametric nodes, the free layout of
// Medit, VTK poly data, strips, pixels, voxels and several VTU pieces.
// Expected counts are worked out by hand in the comments.
#include <gtest/gtest.h>

#include "io_test_support.hpp"

namespace rift::test {
namespace {

// Two unit squares side by side, a quad and two triangles:
//   3---4---5      quad 0 1 4 3, triangles 1 2 5 and 1 5 4
//   |   | / |      edges: 01 12 34 45 03 14 25 15 -> 8, boundary 6
//   0---1---2      darts: two per polygon side
const Counts kQuadAndTwoTriangles{2 * (4 + 3 + 3), 6, 8, 3, 0, 1, 6};

TEST(ObjSyntax, CornerFormsNegativeIndicesAndIgnoredStatements) {
  const std::string text =
      "# exported by hand\r\n"
      "mtllib scene.mtl\r\n"
      "o strip\r\n"
      "v 0 0 0\r\nv 1 0 0\r\nv 2 0 0\r\n"
      "v 0 1 0 1.0\r\n"                     // optional w
      "v 1 1 0\r\nv 2 1 0 0.5 0.5 0.5\r\n"  // vertex colour
      "vt 0 0\r\nvt 1 0\r\nvn 0 0 1\r\n"
      "g left\r\nusemtl red\r\ns off\r\n"
      "f 1/1/1 2/2/1 5/1/1 4/2/1\r\n"
      "g right\r\n"
      "f -5//1 -4//1 -1//1\r\n"  // 2 3 6, relative to the six vertices so far
      "f 2/1 6/2 5/1   # trailing comment\r\n"
      "l 1 2 3\r\n";
  EXPECT_EQ(read_counts(write_temp("strip.obj", text)), kQuadAndTwoTriangles);
  const MeshData mesh = read_mesh_file(write_temp("strip.obj", text));
  ASSERT_EQ(mesh.elements.size(), 3u);
  EXPECT_EQ(mesh.elements[1].source_line, 18);
  const std::uint32_t* v = mesh.vertices_of(mesh.elements[1]);
  EXPECT_EQ((std::vector<std::uint32_t>{v[0], v[1], v[2]}), (std::vector<std::uint32_t>{1, 2, 5}));
}

TEST(ObjSyntax, ExtensionIsCaseInsensitive) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_EQ(read_counts(write_temp("tri.OBJ", text)), (Counts{6, 3, 3, 1, 0, 1, 3}));
}

TEST(GmshSyntax, Version41WithParametricNodesSparseTagsAndExtraSections) {
  // The quad-and-two-triangles strip; node tags 10..60 in three blocks, one of
  // them parametric on a curve (one extra coordinate per node).
  const std::string text =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$PhysicalNames\n1\n2 1 \"sheet\"\n$EndPhysicalNames\n"
      "$Comments\nanything at all, even $Nodes-like words\n$EndComments\n"
      "$Nodes\n3 6 10 60\n"
      "0 1 0 1\n10\n0 0 0\n"
      "1 1 1 2\n20\n30\n1 0 0 0.5\n2 0 0 1.0\n"
      "2 1 0 3\n60\n50\n40\n2 1 0\n1 1 0\n0 1 0\n"
      "$EndNodes\n"
      "$Elements\n2 3 1 3\n"
      "2 1 3 1\n1 10 20 50 40\n"
      "2 1 2 2\n2 20 30 60\n3 20 60 50\n"
      "$EndElements\n"
      "$NodeData\n1\n\"t\"\n1\n0.0\n3\n0\n1\n6\n10 1\n20 1\n30 1\n40 1\n50 1\n60 1\n$EndNodeData\n";
  EXPECT_EQ(read_counts(write_temp("strip41.msh", text)), kQuadAndTwoTriangles);
}

TEST(GmshSyntax, CrlfLineEndingsAndSurfaceWithLines) {
  const std::string text =
      "$MeshFormat\r\n2.2 0 8\r\n$EndMeshFormat\r\n$Nodes\r\n6\r\n"
      "1 0 0 0\r\n2 1 0 0\r\n3 2 0 0\r\n4 0 1 0\r\n5 1 1 0\r\n6 2 1 0\r\n$EndNodes\r\n"
      "$Elements\r\n5\r\n1 1 2 0 1 1 2\r\n2 3 2 0 1 1 2 5 4\r\n3 2 2 0 1 2 3 6\r\n"
      "4 2 2 0 1 2 6 5\r\n5 15 2 0 1 1\r\n$EndElements\r\n";
  const std::string path = write_temp("strip22.msh", text);
  EXPECT_EQ(read_counts(path), kQuadAndTwoTriangles);
  EXPECT_EQ(read_mesh_file(path).dimension, 2);
}

TEST(MeditSyntax, FreeLayoutCommentsAndIgnoredSections) {
  const std::string text =
      "MeshVersionFormatted\n1\n# a comment line\nDimension\n2\n"
      "Vertices 6\n0 0 1  1 0 1  2 0 1\n0 1 1  1 1 1  2 1 1\n"
      "Corners 2 1 3\n"
      "Edges\n2\n1 2 0\n2 3 0\n"
      "Quadrilaterals 1\n1 2 5 4 0\n"
      "Triangles\n2\n2 3 6 0\n2 6 5 0  # the last one\n"
      "Ridges 1 1\n"
      "End\n";
  EXPECT_EQ(read_counts(write_temp("strip.mesh", text)), kQuadAndTwoTriangles);
}

TEST(MeditSyntax, NormalsAndTangentsAreSkippedByTheirRecordSize) {
  const std::string text =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n"
      "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
      "Normals\n2\n0 0 -1\n0 0 1\nNormalAtVertices\n2\n1 1\n2 2\n"
      "Tangents\n1\n1 0 0\nTangentAtVertices\n1\n1 1\n"
      "Tetrahedra\n1\n1 2 3 4 7\nTriangles\n1\n1 2 3 7\nEnd\n";
  EXPECT_EQ(read_counts(write_temp("tet.mesh", text)), (Counts{24, 4, 6, 4, 1, 1, 4}));
}

TEST(VtkSyntax, PolyDataWithPolygonsStripsLinesAndVertices) {
  // A strip of 4 points (2 triangles) and the quad next to it:
  //   2---3---5    strip 0 1 2 3 -> triangles 0 1 2 and 2 1 3
  //   | \ |   |    quad 1 4 5 3
  //   0---1---4    edges 01 12 02 13 23 14 45 35 -> 8, boundary 6
  const std::string text =
      "# vtk DataFile Version 2.0\n\nASCII\nDATASET POLYDATA\n"
      "POINTS 6 float\n0 0 0 1 0 0 0 1 0\n1 1 0 2 0 0 2 1 0\n"
      "VERTICES 1 2\n1 0\n"
      "LINES 1 3\n2 0 1\n"
      "TRIANGLE_STRIPS 1 5\n4 0 1 2 3\n"
      "POLYGONS 1 5\n4 1 4 5 3\n"
      "CELL_DATA 4\nSCALARS c float\nLOOKUP_TABLE default\n1 2 3 4\n";
  EXPECT_EQ(read_counts(write_temp("poly.vtk", text)), (Counts{2 * (3 + 3 + 4), 6, 8, 3, 0, 1, 6}));
}

TEST(VtkSyntax, PixelsAndVoxelsBecomeQuadsAndHexahedra) {
  // A voxel numbers its corners x fastest: 0 (0,0,0), 1 (1,0,0), 2 (0,1,0),
  // 3 (1,1,0), then the same at z = 1. Read as a hexahedron, it is one cube.
  const std::string voxel =
      "# vtk DataFile Version 3.0\nvoxel\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      "POINTS 8 float\n0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1\n"
      "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n11\n";
  EXPECT_EQ(read_counts(write_temp("voxel.vtk", voxel)), (Counts{48, 8, 12, 6, 1, 1, 6}));
  const std::string pixel =
      "# vtk DataFile Version 3.0\npixel\nASCII\nDATASET UNSTRUCTURED_GRID\n"
      "POINTS 4 float\n0 0 0 1 0 0 0 1 0 1 1 0\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n8\n";
  const MeshData mesh = read_mesh_file(write_temp("pixel.vtk", pixel));
  ASSERT_EQ(mesh.elements.size(), 1u);
  // Around the square: 0 1 3 2.
  const std::uint32_t* v = mesh.vertices_of(mesh.elements[0]);
  EXPECT_EQ((std::vector<std::uint32_t>{v[0], v[1], v[2], v[3]}),
            (std::vector<std::uint32_t>{0, 1, 3, 2}));
}

TEST(VtkSyntax, MetadataBlocksAndLowercaseKeywords) {
  const std::string text =
      "# vtk DataFile Version 5.1\ntet\nASCII\ndataset unstructured_grid\n"
      "points 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n"
      "METADATA\nINFORMATION 0\n\n"
      "cells 2 4\noffsets vtktypeint64\n0 4\nconnectivity vtktypeint64\n0 1 2 3\n"
      "cell_types 1\n10\n";
  EXPECT_EQ(read_counts(write_temp("tet.vtk", text)), (Counts{24, 4, 6, 4, 1, 1, 4}));
}

TEST(VtuSyntax, SeveralPiecesAndIgnoredLineCells) {
  // Two pieces, each one triangle; the second also has a line cell. Points of
  // each piece are numbered from 0 within it; the triangles do not share points.
  const std::string piece =
      "<Piece NumberOfPoints=\"3\" NumberOfCells=\"2\"><Points>"
      "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
      "0 0 0 1 0 0 0 1 0</DataArray></Points><Cells>"
      "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 1</DataArray>"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 5</DataArray>"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 3</DataArray>"
      "</Cells></Piece>\n";
  const std::string text =
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n<UnstructuredGrid>\n" + piece + piece +
      "</UnstructuredGrid>\n</VTKFile>\n";
  EXPECT_EQ(read_counts(write_temp("pieces.vtu", text)), (Counts{12, 6, 6, 2, 0, 2, 6}));
}

}  // namespace
}  // namespace rift::test
