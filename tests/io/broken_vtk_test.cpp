// Broken legacy VTK and VTU files: each error names the file, the line of the
// problem and the problem.
#include <gtest/gtest.h>

#include "io_test_support.hpp"

namespace rift::test {
namespace {

// Lines 1-4.
const std::string kGrid = "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\n";
// Lines 5-9: a tetrahedron's four points.
const std::string kTetPoints = "POINTS 4 float\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST(BrokenVtk, EmptyAndNotVtk) {
  expect_broken("empty.vtk", "", 0, "the file is empty");
  expect_broken("other.vtk", "# vtk file\ntest\nASCII\n", 1, "not a legacy VTK file");
}

TEST(BrokenVtk, UnsupportedVersionBinaryAndDataset) {
  expect_broken("version.vtk", "# vtk DataFile Version 7.0\nx\nASCII\n", 1,
                "unsupported VTK file version '7.0'");
  expect_broken("binary.vtk", "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\n",
                3, "binary VTK files are not supported");
  expect_broken("dataset.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\n",
                4, "unsupported VTK dataset type 'STRUCTURED_POINTS'");
}

TEST(BrokenVtk, TruncatedAndShortPoints) {
  expect_broken("truncated.vtk", kGrid + "POINTS 4 float\n0 0 0\n1 0 0\n", 7,
                "unexpected end of file in POINTS (line 5): 6 of 12 announced values were read");
  expect_broken("fewer.vtk", kGrid + "POINTS 4 float\n0 0 0\n1 0 0\n0 1 0\nCELLS 1 5\n", 9,
                "POINTS (line 5) announces 12 values, but 'CELLS' comes after 9");
}

TEST(BrokenVtk, NonFiniteCoordinate) {
  expect_broken("nan.vtk", kGrid + "POINTS 2 float\n0 0 0\n1 -nan 0\n", 7,
                "coordinate 2 of point 1 '-nan' is not a finite number");
}

TEST(BrokenVtk, PointIdOutOfRange) {
  expect_broken("range.vtk", kGrid + kTetPoints + "CELLS 1 5\n4 0 1 2 4\nCELL_TYPES 1\n10\n", 11,
                "cell 0 refers to point 4, but the file has 4 points (numbered from 0)");
}

TEST(BrokenVtk, UnknownCellTypeAndWrongPointCount) {
  // 24 is VTK's quadratic tetrahedron.
  expect_broken("quadratic.vtk", kGrid + kTetPoints + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n24\n",
                13, "unknown or unsupported element type 24");
  expect_broken("count.vtk", kGrid + kTetPoints + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n10\n", 11,
                "cell 0 (tetra) has 3 points, expected 4");
}

TEST(BrokenVtk, CountsThatDoNotAgree) {
  expect_broken("types.vtk", kGrid + kTetPoints + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 2\n10 10\n", 12,
                "CELL_TYPES announces 2 types, but CELLS (line 10) has 1 cells");
  expect_broken("size.vtk", kGrid + kTetPoints + "CELLS 1 6\n4 0 1 2 3\nCELL_TYPES 1\n10\n", 10,
                "CELLS announces a list of 6 values, but its 1 cells hold 5");
  expect_broken("overrun.vtk", kGrid + kTetPoints + "CELLS 1 4\n4 0 1 2 3\nCELL_TYPES 1\n10\n", 11,
                "announces a list of 4 values, but its cells need more");
  expect_broken("offsets.vtk",
                "# vtk DataFile Version 5.1\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n" + kTetPoints +
                    "CELLS 2 4\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2 3\n",
                12, "the last offset should be 4");
}

TEST(BrokenVtk, NoCells) {
  expect_broken("points_only.vtk", kGrid + kTetPoints, 0, "the file has no CELLS section");
  expect_broken("lines_only.vtk", kGrid + kTetPoints + "CELLS 1 3\n2 0 1\nCELL_TYPES 1\n3\n", 0,
                "no polygon or volume element (1 line or point elements were ignored)");
}

// VTU: lines 1-4 open the file, the points array starts on line 5 and
// takes one line per newline in `points`; with four lines of points the
// connectivity is on line 10, the offsets on 11 and the types on 12.
std::string vtu(const std::string& points, const std::string& cells, const std::string& types,
                const std::string& offsets, const std::string& point_format = "ascii") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n"
         "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points>\n"
         "<DataArray NumberOfComponents=\"3\" format=\"" +
         point_format + "\">" + points +
         "</DataArray>\n"
         "</Points><Cells>\n<DataArray Name=\"connectivity\" format=\"ascii\">" +
         cells + "</DataArray>\n<DataArray Name=\"offsets\" format=\"ascii\">" + offsets +
         "</DataArray>\n<DataArray Name=\"types\" format=\"ascii\">" + types +
         "</DataArray>\n</Cells></Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

const std::string kVtuPoints = "0 0 0\n1 0 0\n0 1 0\n0 0 1";  // lines 5-8

TEST(BrokenVtu, ValidReferenceFileReads) {
  // The base of the broken files below, to show that only the change breaks them.
  EXPECT_EQ(read_counts(write_temp("good.vtu", vtu(kVtuPoints, "0 1 2 3", "10", "4"))),
            (Counts{24, 4, 6, 4, 1, 1, 4}));
}

TEST(BrokenVtu, EmptyAndMalformedXml) {
  expect_broken("empty.vtu", "\n", 0, "the file is empty");
  // Cut after line 12 (the types array): the open elements are reported there.
  const std::string good = vtu(kVtuPoints, "0 1 2 3", "10", "4");
  expect_broken("cut.vtu", good.substr(0, good.find("</Cells>")), 12, "malformed XML");
  expect_broken("polydata.vtu", "<VTKFile type=\"PolyData\">\n</VTKFile>\n", 1,
                "unsupported VTK XML dataset type 'PolyData'");
}

TEST(BrokenVtu, BinaryAndAppendedData) {
  // Binary data needs its scalar type; appended data needs the appended block.
  expect_broken("binary.vtu", vtu("AAAAAA==", "0 1 2 3", "10", "4", "binary"), 5,
                "DataArray Points has unknown type ''");
  expect_broken("appended.vtu", vtu("", "0 1 2 3", "10", "4", "appended"), 5,
                "DataArray Points has unknown type ''");
}

TEST(BrokenVtu, WrongValueCounts) {
  expect_broken("few_points.vtu", vtu("0 0 0\n1 0 0\n0 1 0", "0 1 2 3", "10", "4"), 7,
                "DataArray Points (line 5) holds 9 values, 12 expected");
  expect_broken("more_types.vtu", vtu(kVtuPoints, "0 1 2 3", "10 10", "4"), 12,
                "DataArray types holds more than the 1 values expected");
  expect_broken("short_connectivity.vtu", vtu(kVtuPoints, "0 1 2", "10", "4"), 10,
                "DataArray connectivity (line 10) holds 3 values, 4 expected");
}

TEST(BrokenVtu, BadValues) {
  expect_broken("nan.vtu", vtu("0 0 0\n1 0 0\n0 nan 0\n0 0 1", "0 1 2 3", "10", "4"), 7,
                "coordinate 2 of point 2 'nan' is not a finite number");
  expect_broken("range.vtu", vtu(kVtuPoints, "0 1 2 7", "10", "4"), 10,
                "cell 0 refers to point 7, but the file has 4 points");
  expect_broken("type.vtu", vtu(kVtuPoints, "0 1 2 3", "25", "4"), 12,
                "unknown or unsupported element type 25");
}

}  // namespace
}  // namespace rift::test
