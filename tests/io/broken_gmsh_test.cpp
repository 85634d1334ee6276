// Broken Gmsh files: each error names the file, the line of the problem and
// the problem. Line numbers are counted in the comments next to the text.
#include <gtest/gtest.h>

#include "io_test_support.hpp"

namespace rift::test {
namespace {

const std::string kHeader22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";  // lines 1-3
// Lines 4-10: four nodes of a unit square.
const std::string kNodes22 = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n";

TEST(BrokenGmsh, EmptyFile) {
  expect_broken("empty.msh", "", 0, "the file is empty");
  expect_broken("blank.msh", "\n  \n\t\n", 0, "the file is empty");
}

TEST(BrokenGmsh, NotAGmshFile) {
  expect_broken("text.msh", "\nhello world\n", 2, "not a Gmsh file");
}

TEST(BrokenGmsh, TruncatedInsideNodes) {
  expect_broken("truncated.msh", kHeader22 + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n", 7,
                "unexpected end of file in $Nodes: 2 of the 4 announced nodes were read");
}

TEST(BrokenGmsh, TruncatedInsideALine) {
  expect_broken("cut_line.msh", kHeader22 + "$Nodes\n4\n1 0 0 0\n2 1 0", 7,
                "line ends early, expected the z coordinate of node 2");
}

TEST(BrokenGmsh, MissingSectionEnd) {
  expect_broken("no_end.msh", kHeader22 + kNodes22 + "$Elements\n1\n1 2 2 0 1 1 2 3\n", 13,
                "section $Elements (line 11) has no $EndElements");
  expect_broken("no_end_format.msh", "$MeshFormat\n2.2 0 8\n$Nodes\n", 3,
                "expected $EndMeshFormat");
}

TEST(BrokenGmsh, FewerNodesThanAnnounced) {
  expect_broken("fewer.msh", kHeader22 + "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n$EndNodes\n", 9,
                "section $Nodes announces 5 nodes but holds 3");
}

TEST(BrokenGmsh, MoreElementsThanAnnounced) {
  expect_broken(
      "more.msh",
      kHeader22 + kNodes22 + "$Elements\n1\n1 2 2 0 1 1 2 3\n2 2 2 0 1 1 3 4\n$EndElements\n", 14,
      "section $Elements holds more than the 1 elements it announces");
}

TEST(BrokenGmsh, UndefinedNodeTag) {
  expect_broken(
      "undefined.msh",
      kHeader22 + kNodes22 + "$Elements\n2\n1 2 2 0 1 1 2 3\n2 2 2 0 1 1 3 9\n$EndElements\n", 14,
      "element 2 refers to node 9, which is not defined");
}

TEST(BrokenGmsh, DuplicateNodeTag) {
  expect_broken("duplicate.msh", kHeader22 + "$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n", 7,
                "node 1 is defined twice");
}

TEST(BrokenGmsh, NonFiniteAndUnparsableCoordinates) {
  expect_broken("nan.msh", kHeader22 + "$Nodes\n2\n1 0 0 0\n2 1 nan 0\n$EndNodes\n", 7,
                "the y coordinate of node 2 'nan' is not a finite number");
  expect_broken("inf.msh", kHeader22 + "$Nodes\n2\n1 0 0 -inf\n2 1 0 0\n$EndNodes\n", 6,
                "is not a finite number");
  expect_broken("garbage.msh", kHeader22 + "$Nodes\n2\n1 0 0 0\n2 1.2.3 0 0\n$EndNodes\n", 7,
                "expected the x coordinate of node 2 (a number), found '1.2.3'");
  expect_broken("huge.msh", kHeader22 + "$Nodes\n1\n1 0 1e999 0\n$EndNodes\n", 6, "out of range");
}

TEST(BrokenGmsh, UnknownElementType) {
  // Type 11 is the 10-node (quadratic) tetrahedron.
  expect_broken(
      "tet10.msh",
      kHeader22 + kNodes22 + "$Elements\n1\n1 11 2 0 1 1 2 3 4 1 2 3 4 1 2\n$EndElements\n", 13,
      "unknown or unsupported element type 11");
}

TEST(BrokenGmsh, UnsupportedVersionsAndBinary) {
  expect_broken("v3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", 2,
                "unsupported Gmsh format version 3.0");
  expect_broken("v40.msh", "$MeshFormat\n4 0 8\n$EndMeshFormat\n", 2,
                "unsupported Gmsh format version 4");
  // Binary files are read (binary_formats_test.cpp); one cut in its marker.
  expect_broken("binary.msh", "$MeshFormat\n4.1 1 8\n\x01", 3,
                "unexpected end of file in binary data at byte 20, expected the binary marker");
  expect_broken("size.msh", "$MeshFormat\n4.1 1 6\n", 2, "data size 6 is not 4 or 8");
}

TEST(BrokenGmsh, NoElementsAtAll) {
  expect_broken("lines_only.msh",
                kHeader22 + kNodes22 + "$Elements\n2\n1 1 2 0 1 1 2\n2 15 2 0 1 3\n$EndElements\n",
                11, "no polygon or volume element (2 line or point elements were ignored)");
  expect_broken("no_nodes.msh", kHeader22, 0, "the file has no $Nodes section");
  expect_broken("no_elements.msh", kHeader22 + kNodes22, 0, "no polygon or volume element");
}

TEST(BrokenGmsh, RepeatedVertexInAnElementIsReportedAtItsLine) {
  expect_broken(
      "repeat.msh",
      kHeader22 + kNodes22 + "$Elements\n2\n1 2 2 0 1 1 2 3\n2 2 2 0 1 1 3 3\n$EndElements\n", 14,
      "repeats vertex");
}

TEST(BrokenGmsh, Version1WrongNodeCountAndTruncation) {
  const std::string nodes = "$NOD\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$ENDNOD\n";  // lines 1-6
  expect_broken("v1_count.msh", nodes + "$ELM\n1\n1 2 1 1 4 1 2 3 3\n$ENDELM\n", 9,
                "triangle 1 has 4 nodes, expected 3");
  expect_broken("v1_truncated.msh", nodes + "$ELM\n2\n1 2 1 1 3 1 2 3\n", 9,
                "unexpected end of file in $ELM: 1 of the 2 announced elements were read");
  expect_broken("v1_noend.msh", "$NOD\n1\n1 0 0 0\n$ELM\n", 4, "expected $ENDNOD");
}

TEST(BrokenGmsh, Version41BlockCountsThatDoNotAddUp) {
  const std::string header = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";  // lines 1-3
  // The header announces 4 nodes, the only block holds 3.
  expect_broken("v41_nodes.msh",
                header + "$Nodes\n1 4 1 4\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n", 5,
                "section $Nodes announces 4 nodes but its blocks hold 3");
  // A block holds more elements than the header announces.
  expect_broken("v41_elements.msh",
                header + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n" +
                    "$Elements\n1 1 1 1\n2 1 2 2\n1 1 2 3\n2 1 3 2\n$EndElements\n",
                16, "section $Elements announces 1 elements but its blocks hold more");
  // An element refers to a node no block defines.
  expect_broken("v41_undefined.msh",
                header + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n" +
                    "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 7\n$EndElements\n",
                17, "element 1 refers to node 7, which is not defined");
}

}  // namespace
}  // namespace rift::test
