// Hostile meshes: lying headers, indices and coordinates out of any sane
// range, degenerate and inverted elements, encodings and sizes that break
// naive readers. Each gives a located message (or is read by a documented
// rule, checked here), never a crash, a hang or an allocation the data does
// not justify. Big inputs are generated here, not stored.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io_test_support.hpp"
#include "rift/io/readers.hpp"
#include "shapes.hpp"

namespace rift::test {
namespace {

const std::string kTet = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";

TEST(HostileInputs, HeadersAnnouncingBillionsOfEntries) {
  // The data shows three nodes: the claim is reported when the data runs out,
  // and nothing is reserved for it before (reservation_test.cpp).
  expect_broken("nodes.msh", kTet + "$Nodes\n2147483647\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n", 9,
                "section $Nodes announces 2147483647 nodes but holds 3");
  expect_broken("too_many.msh", kTet + "$Nodes\n2147483648\n", 5,
                "the number of nodes '2147483648' is too large");
  expect_broken("elements.msh",
                kTet +
                    "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n"
                    "1999999999\n1 2 0 1 2 3\n",
                12, "unexpected end of file in $Elements: 1 of the 1999999999 announced elements");
  expect_broken("points.vtk",
                "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                "POINTS 2000000000 double\n0 0 0\n",
                6, "3 of 6000000000 announced values were read");
  expect_broken("vertices.mesh",
                "MeshVersionFormatted 2\nDimension 3\nVertices\n2000000000\n0 0 0 0\n", 5,
                "2000000000");
  expect_broken("cells.vtu",
                "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>\n"
                "<Piece NumberOfPoints=\"2000000000\" NumberOfCells=\"2000000000\"><Points>\n"
                "<DataArray NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray>\n"
                "</Points></Piece></UnstructuredGrid></VTKFile>\n",
                3, "DataArray Points (line 3) holds 3 values, 6000000000 expected");
}

TEST(HostileInputs, NegativeAndOverflowingIndices) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_broken("negative.obj", tri + "f 1 2 -9\n", 4,
                "relative vertex index -9 reaches before the first vertex (3 defined so far)");
  expect_broken("overflow.obj", tri + "f 1 2 99999999999999999999\n", 4,
                "a vertex index '99999999999999999999' is out of range");
  expect_broken("beyond.obj", tri + "f 1 2 4294967297\n", 4,
                "face refers to vertex 4294967297, but the file defines 3 vertices");
  expect_broken("negative.msh",
                kTet +
                    "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n"
                    "1 2 0 1 2 -3\n$EndElements\n",
                12, "element 1 refers to node -3, which is not defined");
  expect_broken("negative_count.msh", kTet + "$Nodes\n-5\n", 5,
                "the number of nodes is negative ('-5')");
}

TEST(HostileInputs, SparseHugeAndRepeatedNodeTags) {
  // Tags far apart (the hash map) and near (the flat table) mix freely.
  const MeshData mesh =
      io::read_gmsh("sparse.msh", kTet +
                                      "$Nodes\n4\n9000000000000000000 0 0 0\n5 1 0 0\n-7 0 1 0\n"
                                      "2000000 0 0 1\n$EndNodes\n$Elements\n1\n"
                                      "1 4 0 9000000000000000000 5 -7 2000000\n$EndElements\n");
  EXPECT_EQ(mesh.element_vertices, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  expect_broken("twice_dense.msh", kTet + "$Nodes\n2\n5 0 0 0\n5 1 0 0\n$EndNodes\n", 7,
                "node 5 is defined twice");
  expect_broken("twice_sparse.msh", kTet + "$Nodes\n2\n-5 0 0 0\n-5 1 0 0\n$EndNodes\n", 7,
                "node -5 is defined twice");
}

TEST(HostileInputs, NonFiniteAndHugeCoordinates) {
  const std::string rest = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
  expect_broken("nan.obj", "v nan 0 0\n" + rest, 1,
                "a vertex coordinate 'nan' is not a finite number");
  expect_broken("inf.obj", "v 0 -inf 0\n" + rest, 1, "a vertex coordinate '-inf' is not a finite");
  expect_broken("e400.obj", "v 0 0 1e400\n" + rest, 1,
                "a vertex coordinate '1e400' is out of range");
  // 1e300 is a double, but its square is not: areas and masses would be NaN.
  expect_broken(
      "e300.obj", "v 1e300 0 0\n" + rest, 1,
      "a vertex coordinate '1e300' is beyond +-1e30, the largest coordinate rift accepts");
  expect_broken("e300.msh", kTet + "$Nodes\n1\n1 0 -1e300 0\n$EndNodes\n", 6,
                "the y coordinate of node 1 '-1e300' is beyond +-1e30");
  // The same rule after placement (a scene's scale), without a line.
  MeshData mesh = io::read_obj("big.obj", "v 0 0 0\n" + rest);
  mesh.points[1].x() = 1e31;
  try {
    assemble_gmap(mesh);
    ADD_FAILURE() << "no error";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 2 has a coordinate beyond +-1e30"),
              std::string::npos)
        << e.what();
  }
}

AssemblyReport report_of(const MeshData& mesh) {
  AssemblyReport report;
  const GMap map = assemble_gmap(mesh, &report);
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
  return report;
}

std::string warnings_of(const AssemblyReport& report, int dimension) {
  std::string all;
  for (const std::string& w : assembly_warnings(report, dimension))
    all += w + "\n";
  return all;
}

TEST(HostileInputs, ZeroAreaAndZeroVolumeElementsAreKeptAndNamed) {
  // Rule: kept as they are (they carry no mass), counted, the first one named.
  const MeshData flat_triangle =
      io::read_obj("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
  const AssemblyReport r = report_of(flat_triangle);
  EXPECT_EQ(r.flat_elements, 1u);
  EXPECT_EQ(r.first_flat.index, 1u);
  EXPECT_EQ(r.first_flat.line, 6);
  EXPECT_EQ(
      warnings_of(r, 2),
      "1 elements have zero area and carry no mass or stiffness (first: polygon 2, line 6)\n");

  MeshData tet;
  tet.dimension = 3;
  tet.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  tet.add_element(ElementType::Tetra, {0, 1, 2, 3}, 9);
  const AssemblyReport t = report_of(tet);
  EXPECT_EQ(t.flat_elements, 1u);
  EXPECT_EQ(t.reoriented_solids, 0u);
  EXPECT_NE(warnings_of(t, 3).find("zero volume"), std::string::npos);
}

MeshData unit_hex(bool inverted) {
  MeshData m;
  m.dimension = 3;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
              Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  if (inverted) {
    m.add_element(ElementType::Hexa, {4, 5, 6, 7, 0, 1, 2, 3}, 3);
  } else {
    m.add_element(ElementType::Hexa, {0, 1, 2, 3, 4, 5, 6, 7}, 3);
  }
  return m;
}

TEST(HostileInputs, InvertedSolidsOfEveryTypeAreReoriented) {
  EXPECT_EQ(report_of(unit_hex(false)).reoriented_solids, 0u);
  const AssemblyReport h = report_of(unit_hex(true));
  EXPECT_EQ(h.reoriented_solids, 1u);
  EXPECT_EQ(warnings_of(h, 3), "1 inverted solids were reoriented (first: hexahedron 1, line 3)\n");

  MeshData wedge;  // VTK: the first triangle's normal points away from the second
  wedge.dimension = 3;
  wedge.points = {Vec3(0, 0, 0),  Vec3(1, 0, 0),  Vec3(0, 1, 0),
                  Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0, 1, -1)};
  wedge.add_element(ElementType::Wedge, {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(report_of(wedge).reoriented_solids, 0u);
  wedge.element_vertices = {3, 4, 5, 0, 1, 2};
  EXPECT_EQ(report_of(wedge).reoriented_solids, 1u);

  MeshData pyramid;
  pyramid.dimension = 3;
  pyramid.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 1)};
  pyramid.add_element(ElementType::Pyramid, {0, 1, 2, 3, 4});
  EXPECT_EQ(report_of(pyramid).reoriented_solids, 0u);
  pyramid.element_vertices = {0, 3, 2, 1, 4};
  EXPECT_EQ(report_of(pyramid).reoriented_solids, 1u);

  // The shapes of every format are positively oriented and not flat.
  for (const Shape& s : shapes()) {
    MeshData m;
    m.dimension = s.dimension;
    m.points = s.points;
    for (const ShapeElement& e : s.elements)
      m.add_element(e.type, e.v.begin(), e.v.end());
    const AssemblyReport r = report_of(m);
    EXPECT_EQ(r.reoriented_solids, 0u) << s.name;
    EXPECT_EQ(r.flat_elements, 0u) << s.name;
    EXPECT_EQ(r.tangled_solids, 0u) << s.name;
  }
}

TEST(HostileInputs, CollapsedAndTangledHexahedra) {
  // Top on the bottom with distinct vertices: zero volume, kept and named.
  MeshData collapsed = unit_hex(false);
  for (int k = 4; k < 8; ++k)
    collapsed.points[static_cast<std::size_t>(k)].z() = 0;
  const AssemblyReport c = report_of(collapsed);
  EXPECT_EQ(c.flat_elements, 1u);
  EXPECT_EQ(c.reoriented_solids, 0u);
  // One top corner pushed through the bottom: corners disagree.
  MeshData tangled = unit_hex(false);
  tangled.points[6] = Vec3(1, 1, -3);
  const AssemblyReport t = report_of(tangled);
  EXPECT_EQ(t.tangled_solids, 1u);
  EXPECT_NE(warnings_of(t, 3).find("1 solids are tangled"), std::string::npos);
  // A collapsed element spelled with repeated vertices is refused, with a hint.
  expect_broken("collapsed.vtk",
                "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 6 double\n"
                "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\nCELLS 1 9\n8 0 1 2 3 4 5 5 4\n"
                "CELL_TYPES 1\n12\n",
                13,
                "repeats vertex 6 (a collapsed element: write it as the element it collapses to");
}

TEST(HostileInputs, MixedDimensionsKeepTheSolids) {
  // The documented rule: solids make a 3D mesh, polygons are then boundary markers.
  const MeshData mesh = io::read_gmsh(
      "mixed.msh", kTet +
                       "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                       "$Elements\n3\n1 2 0 1 2 3\n2 4 0 1 2 3 4\n3 1 0 1 2\n$EndElements\n");
  EXPECT_EQ(mesh.dimension, 3);
  ASSERT_EQ(mesh.elements.size(), 1u);
  EXPECT_EQ(mesh.elements[0].type, ElementType::Tetra);
}

// Every format, with CRLF line ends and with a UTF-8 byte-order mark, reads
// to the same mesh as the plain file.
TEST(HostileInputs, CrlfAndByteOrderMarkReadLikeThePlainFile) {
  using ReadFn = MeshData (*)(const std::string&, std::string_view);
  const Shape s = shapes()[1];
  const std::pair<ReadFn, std::string> files[] = {{io::read_obj, to_obj(s)},
                                                  {io::read_gmsh, to_gmsh12(s, 2)},
                                                  {io::read_gmsh, to_gmsh41(s)},
                                                  {io::read_medit, to_medit(s)},
                                                  {io::read_vtk_legacy, to_vtk(s, false)},
                                                  {io::read_vtu, to_vtu(s)}};
  for (const auto& [read, text] : files) {
    const MeshData plain = read("plain", text);
    std::string crlf;
    for (char c : text) {
      if (c == '\n') crlf += '\r';
      crlf += c;
    }
    for (const std::string& variant : {crlf, "\xEF\xBB\xBF" + text, "\xEF\xBB\xBF" + crlf}) {
      MeshData got;
      ASSERT_NO_THROW(got = read("variant", variant)) << text.substr(0, 30);
      EXPECT_EQ(got.points, plain.points);
      EXPECT_EQ(got.element_vertices, plain.element_vertices);
    }
  }
}

TEST(HostileInputs, NulBytesAreALocatedError) {
  using namespace std::string_literals;
  expect_broken("nul.obj", "v 0 0 0\nv 1 0 0\nv 0 1\0 0\nf 1 2 3\n"s, 3,
                "expected a vertex coordinate (a number), found '1?'");
  expect_broken("nul.msh", kTet + "$Nodes\n1\n1 0 0 0\0\n$EndNodes\n"s, 6,
                "expected the z coordinate of node 1 (a number), found '0?'");
  // Only the text before the NUL is XML.
  std::string vtu = to_vtu(shapes()[0]);
  vtu[vtu.find("<Points>")] = '\0';
  try {
    io::read_vtu("nul.vtu", vtu);
    ADD_FAILURE() << "no error";
  } catch (const MeshError& e) {
    EXPECT_GT(e.line(), 0) << e.what();
  }
}

TEST(HostileInputs, AHundredMegabyteLine) {
  // A 100 MB comment is skipped; a 100 MB number is one message, quoted short.
  std::string text =
      "# " + std::string(100'000'000, 'x') + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_EQ(io::read_obj("long_comment.obj", text).points.size(), 3u);
  text = "v " + std::string(100'000'000, '1') + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  try {
    io::read_obj("long_number.obj", text);
    ADD_FAILURE() << "no error";
  } catch (const MeshError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("long_number.obj:1: error: a vertex coordinate '1111"), std::string::npos);
    EXPECT_LT(what.size(), 200u);
  }
}

TEST(HostileInputs, DeeplyNestedXml) {
  // pugixml parses nesting without recursion; the reader looks only where a
  // VTU has its elements, so a million levels are read and reported.
  constexpr int kDepth = 1'000'000;
  std::string text = "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>\n";
  text.reserve(text.size() + 8 * kDepth);
  for (int k = 0; k < kDepth; ++k)
    text += "<a>";
  for (int k = 0; k < kDepth; ++k)
    text += "</a>";
  text += "\n</UnstructuredGrid></VTKFile>\n";
  try {
    io::read_vtu("deep.vtu", text);
    ADD_FAILURE() << "no error";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("deep.vtu:1: error: the UnstructuredGrid has no Piece"),
              std::string::npos)
        << e.what();
  }
}

TEST(HostileInputs, ASinglePolygonOfThreeHundredThousandVertices) {
  // A repeated-vertex check per pair made this quadratic (12 s in `rift info`);
  // it is now one pass. Correctness here; the speed is in the benchmarks.
  constexpr std::uint32_t kCorners = 300'000;
  MeshData mesh;
  mesh.points.reserve(kCorners);
  std::vector<std::uint32_t> ids(kCorners);
  for (std::uint32_t k = 0; k < kCorners; ++k) {
    const double a = 2 * 3.141592653589793 * k / kCorners;
    mesh.points.emplace_back(std::cos(a), std::sin(a), 0);
    ids[k] = k;
  }
  mesh.add_element(ElementType::Polygon, ids.begin(), ids.end(), 1);
  AssemblyReport report;
  const GMap map = assemble_gmap(mesh, &report);
  const Counts c = counts_of(map);
  EXPECT_EQ(c.vertices, kCorners);
  EXPECT_EQ(c.faces, 1u);
  EXPECT_EQ(c.boundary, kCorners);
  EXPECT_EQ(report.flat_elements, 0u);
  // The same polygon with its last vertex repeated is refused.
  mesh.element_vertices.back() = 17;
  EXPECT_THROW(assemble_gmap(mesh), MeshError);
}

}  // namespace
}  // namespace rift::test
