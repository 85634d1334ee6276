// A header that announces billions of entries allocates nothing before its
// data is there (issue 13): the readers' vectors grow with the entries read,
// never past the announced count. Every operator new of this test binary is
// watched (allocation_watch.hpp) for its largest single request while a reader runs on a file whose
// header lies (2^31 - 1 announced, a few thousand present) and on the same
// file with an honest header.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>

#include "allocation_watch.hpp"
#include "rift/io/readers.hpp"
#include "rift/mesh/mesh_error.hpp"

namespace rift::test {
namespace {

using Reader = std::function<MeshData(const std::string&, std::string_view)>;

/// The largest single allocation while `read` runs on `text` (which may
/// throw: a lying header ends in a located error).
std::size_t largest_allocation(const Reader& read, const std::string& text, std::string* error) {
  test_support::reset_largest_allocation();
  try {
    read("f", text);
  } catch (const MeshError& e) {
    *error = e.what();
  }
  return test_support::largest_allocation();
}

constexpr std::size_t kEntries = 20'000;
constexpr const char* kBillions = "2147483647";

std::string numbered(std::size_t n, const std::function<std::string(std::size_t)>& line) {
  std::string out;
  for (std::size_t k = 0; k < n; ++k)
    out += line(k);
  return out;
}

std::string xyz(std::size_t k) {
  return std::to_string(k % 100) + ".5 " + std::to_string(k % 7) + " " + std::to_string(k % 3);
}

struct Case {
  const char* name;
  Reader read;
  std::function<std::string(const std::string& count)> file;  // with the count given
  std::size_t entry_bytes;  // memory per entry of the vector the count sizes
  const char* message;      // what the located error says
};

TEST(HostileInputs, LyingHeadersAllocateAtMostTwiceTheDataPresent) {
  const std::string tail_tri = "$Elements\n1\n1 2 0 1 2 3\n$EndElements\n";
  const std::vector<Case> cases = {
      {"gmsh 2.2 $Nodes", io::read_gmsh,
       [&](const std::string& n) {
         return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + n + "\n" +
                numbered(
                    kEntries,
                    [](std::size_t k) { return std::to_string(k + 1) + " " + xyz(k) + "\n"; }) +
                "$EndNodes\n" + tail_tri;
       },
       sizeof(Vec3), "section $Nodes announces 2147483647 nodes but holds 20000"},
      {"gmsh 4.1 $Nodes", io::read_gmsh,
       [&](const std::string& n) {
         return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 " + n + " 1 " + n + "\n2 1 0 " +
                std::to_string(kEntries) + "\n" +
                numbered(kEntries, [](std::size_t k) { return std::to_string(k + 1) + "\n"; }) +
                numbered(kEntries, [](std::size_t k) { return xyz(k) + "\n"; }) +
                "$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
       },
       sizeof(Vec3), "section $Nodes announces 2147483647 nodes but its blocks hold 20000"},
      {"Medit Vertices", io::read_medit,
       [&](const std::string& n) {
         return "MeshVersionFormatted 2\nDimension 3\nVertices\n" + n + "\n" +
                numbered(kEntries, [](std::size_t k) { return xyz(k) + " 0\n"; }) +
                "Triangles\n1\n1 2 3 0\nEnd\n";
       },
       sizeof(Vec3), "Vertices (line 3) announces 2147483647 entries but holds 20000"},
      {"VTK POINTS", io::read_vtk_legacy,
       [&](const std::string& n) {
         return "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " + n +
                " double\n" + numbered(kEntries, [](std::size_t k) { return xyz(k) + "\n"; }) +
                "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n";
       },
       sizeof(Vec3), "POINTS (line 5) announces 6442450941 values, but 'CELLS' comes after 60000"},
      {"VTK CELLS", io::read_vtk_legacy,
       [&](const std::string& n) {
         return "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 "
                "double\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 " +
                n + "\n" + std::to_string(kEntries) + " " +
                numbered(kEntries, [](std::size_t k) { return std::to_string(k % 3) + " "; }) +
                "\nCELL_TYPES 1\n7\n";
       },
       sizeof(std::uint32_t),
       "CELLS announces a list of 2147483647 values, but its 1 cells hold 20001"},
      {"VTU offsets", io::read_vtu,
       [&](const std::string& n) {
         return "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>\n<Piece "
                "NumberOfPoints=\"3\" "
                "NumberOfCells=\"" +
                n +
                "\"><Points><DataArray NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 "
                "0</DataArray></Points><Cells>\n<DataArray Name=\"connectivity\" "
                "format=\"ascii\">0 1 2</DataArray>\n<DataArray Name=\"offsets\" "
                "format=\"ascii\">" +
                numbered(kEntries, [](std::size_t) { return "3 "; }) +
                "</DataArray>\n<DataArray Name=\"types\" format=\"ascii\">5</DataArray>\n"
                "</Cells></Piece></UnstructuredGrid></VTKFile>\n";
       },
       sizeof(std::size_t), "DataArray offsets (line 4) holds 20000 values, 2147483647 expected"},
  };
  for (const Case& c : cases) {
    const std::string lying = c.file(kBillions);
    std::string error;
    const std::size_t largest = largest_allocation(c.read, lying, &error);
    EXPECT_NE(error.find(c.message), std::string::npos) << c.name << ": " << error;
    // The vector the count sizes ends at most twice the entries present; any
    // other allocation (the XML document, a message) is below the file's size.
    const std::size_t data_bound = 2 * kEntries * c.entry_bytes;
    EXPECT_LE(largest, std::max(data_bound, lying.size() + 4096))
        << c.name << ": largest allocation " << largest << " bytes for " << kEntries
        << " entries in a file of " << lying.size() << " bytes";
  }
}

TEST(HostileInputs, HonestHeadersKeepTheirExactSize) {
  std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + std::to_string(kEntries) + "\n";
  for (std::size_t k = 0; k < kEntries; ++k)
    text += std::to_string(k + 1) + " " + xyz(k) + "\n";
  text += "$EndNodes\n$Elements\n1\n1 2 0 1 2 3\n$EndElements\n";
  const MeshData mesh = io::read_gmsh("honest.msh", text);
  EXPECT_EQ(mesh.points.size(), kEntries);
  EXPECT_EQ(mesh.points.capacity(), kEntries);
}

}  // namespace
}  // namespace rift::test
