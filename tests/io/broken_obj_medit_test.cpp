// Broken OBJ and Medit files: each error names the file, the line of the
// problem and the problem.
#include <gtest/gtest.h>

#include "io_test_support.hpp"

namespace rift::test {
namespace {

const std::string kTriangleVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1-3

TEST(BrokenObj, EmptyFile) {
  expect_broken("empty.obj", "", 0, "the file is empty");
}

TEST(BrokenObj, VertexWithTooFewCoordinates) {
  expect_broken("short.obj", "v 0 0 0\nv 1 0\nf 1 2 1\n", 2,
                "vertex 2 has 2 coordinates, expected 3");
}

TEST(BrokenObj, NonFiniteAndUnparsableCoordinates) {
  expect_broken("nan.obj", "v 0 0 0\nv 1 NaN 0\nv 0 1 0\nf 1 2 3\n", 2,
                "'NaN' is not a finite number");
  expect_broken("text.obj", "v 0 0 0\nv 1 0 0\nv zero 1 0\nf 1 2 3\n", 3,
                "expected a vertex coordinate (a number), found 'zero'");
}

TEST(BrokenObj, IndexOutOfRange) {
  expect_broken("range.obj", kTriangleVertices + "f 1 2 3\nf 1 2 9\n", 5,
                "face refers to vertex 9, but the file defines 3 vertices");
  expect_broken("zero.obj", kTriangleVertices + "f 0 1 2\n", 4, "vertex index 0 is invalid");
  expect_broken("relative.obj", kTriangleVertices + "\n\nf -1 -2 -4\n", 6,
                "relative vertex index -4 reaches before the first vertex (3 defined so far)");
  expect_broken("index_text.obj", kTriangleVertices + "f 1 x/1 3\n", 4,
                "expected a vertex index (an integer), found 'x'");
}

TEST(BrokenObj, DegenerateFaces) {
  expect_broken("two.obj", kTriangleVertices + "f 1 2\n", 4, "face has 2 vertices, at least 3");
  expect_broken("repeat.obj", kTriangleVertices + "v 1 1 0\nf 1 2 3\nf 2 4 4\n", 6,
                "repeats vertex 4");
}

TEST(BrokenObj, UnknownStatement) {
  expect_broken("unknown.obj", kTriangleVertices + "f 1 2 3\nfrobnicate 1\n", 5,
                "unknown OBJ statement 'frobnicate'");
}

TEST(BrokenObj, NoFaces) {
  expect_broken("no_faces.obj", kTriangleVertices + "l 1 2 3\n", 0,
                "no polygon or volume element (1 line or point elements were ignored)");
}

// Lines 1-8: version, dimension and four vertices.
const std::string kMeditTetVertices =
    "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n"
    "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";

TEST(BrokenMedit, EmptyAndNotMedit) {
  expect_broken("empty.mesh", "  \n", 0, "the file is empty");
  expect_broken("other.mesh", "# comment\nVertices 3\n", 2,
                "not a Medit mesh: expected MeshVersionFormatted, found 'Vertices'");
}

TEST(BrokenMedit, UnsupportedVersionAndDimension) {
  expect_broken("version.mesh", "MeshVersionFormatted\n\n5\nDimension 3\nEnd\n", 3,
                "unsupported Medit format version '5'");
  expect_broken("dimension.mesh", "MeshVersionFormatted 1\nDimension\n4\nEnd\n", 3,
                "unsupported dimension '4'");
}

TEST(BrokenMedit, Truncated) {
  expect_broken("truncated.mesh",
                "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0", 6,
                "unexpected end of file in Vertices: 1 of the 4 announced entries were read");
  expect_broken("no_end.mesh", kMeditTetVertices + "Tetrahedra\n1\n1 2 3 4 0\n", 11,
                "the mesh has no End keyword");
}

TEST(BrokenMedit, WrongCounts) {
  expect_broken("fewer.mesh", kMeditTetVertices + "Tetrahedra\n2\n1 2 3 4 0\nEnd\n", 12,
                "Tetrahedra (line 9) announces 2 entries but holds 1");
  expect_broken("more.mesh", kMeditTetVertices + "Tetrahedra\n1\n1 2 3 4 0\n1 2 4 3 0\nEnd\n", 12,
                "expected a Medit keyword, found '1'");
}

TEST(BrokenMedit, VertexOutOfRange) {
  expect_broken("range.mesh", kMeditTetVertices + "Tetrahedra\n1\n1 2 3\n5 0\nEnd\n", 12,
                "Tetrahedra entry 1 refers to vertex 5, but the mesh has 4 vertices");
}

TEST(BrokenMedit, NonFiniteCoordinate) {
  expect_broken("nan.mesh",
                "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 inf 0 0\nEnd\n", 6,
                "coordinate 2 of vertex 2 'inf' is not a finite number");
}

TEST(BrokenMedit, UnknownKeywordAndMisplacedElements) {
  expect_broken("keyword.mesh", kMeditTetVertices + "Polyhedra\n0\nEnd\n", 9,
                "unknown Medit keyword 'Polyhedra'");
  expect_broken("dim2.mesh",
                "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
                "Tetrahedra\n1\n1 2 3 4 0\nEnd\n",
                11, "Tetrahedra in a mesh of dimension 2");
}

// A record of normals holds `dimension` values: before Dimension it held none,
// and a count of 10^18 looped without reading (found by the fuzzer).
TEST(BrokenMedit, NormalsBeforeDimension) {
  expect_broken("normals.mesh", "MeshVersionFormatted 2\nNormals\n1000000000000000000\nEnd\n", 2,
                "Normals before Dimension");
  expect_broken("tangents.mesh", "MeshVersionFormatted 2\n\nTangents 3\n1 0 0\nEnd\n", 3,
                "Tangents before Dimension");
}

TEST(BrokenMedit, NoElements) {
  expect_broken("edges.mesh", kMeditTetVertices + "Edges\n1\n1 2 0\nEnd\n", 0,
                "no polygon or volume element (1 line or point elements were ignored)");
}

}  // namespace
}  // namespace rift::test
