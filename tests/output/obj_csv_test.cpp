#include <gtest/gtest.h>

#include <cerrno>
#include <sstream>

#include "output_test_support.hpp"
#include "rift/output/csv_writer.hpp"
#include "rift/output/frame_mesh.hpp"
#include "rift/output/obj_writer.hpp"
#include "rift/output/output_error.hpp"

namespace rift {
namespace {

using test::fresh_folder;
using test::read_lines;

struct ObjCounts {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t torn_groups = 0;
  bool indices_in_range = true;
};

ObjCounts count_obj(const std::filesystem::path& path) {
  ObjCounts c;
  for (const std::string& line : read_lines(path)) {
    if (line.rfind("v ", 0) == 0) ++c.vertices;
    if (line == "g torn") ++c.torn_groups;
    if (line.rfind("f ", 0) != 0) continue;
    ++c.faces;
    std::istringstream in(line.substr(2));
    for (long index; in >> index;) {
      if (index < 1 || static_cast<std::size_t>(index) > c.vertices) c.indices_in_range = false;
    }
  }
  return c;
}

TEST(Obj, ClothHasItsVerticesAndFaces) {
  const auto dir = fresh_folder();
  GMap map = test::quad_cloth(5, 4);
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  FrameExtractor extractor(options);
  ObjWriter writer;
  writer.write(extractor.extract(map), dir / "a.obj");
  const ObjCounts a = count_obj(dir / "a.obj");
  EXPECT_EQ(a.vertices, 30u);
  EXPECT_EQ(a.faces, 20u);
  EXPECT_TRUE(a.indices_in_range);
  EXPECT_EQ(a.torn_groups, 0u);

  const Dart d = test::sewn_dart_on_edge(map, Vec3(0.2, 0, 0), Vec3(0.2, 0.25, 0));
  ASSERT_NE(d, kNoDart);
  map.unsew(d, 2);
  writer.write(extractor.extract(map), dir / "b.obj");
  const ObjCounts b = count_obj(dir / "b.obj");
  EXPECT_EQ(b.vertices, 31u);
  EXPECT_EQ(b.faces, 20u);
  EXPECT_GE(b.torn_groups, 1u);
}

TEST(Obj, BlockShowsOnlyItsSurface) {
  const auto dir = fresh_folder();
  ObjWriter().write(extract_frame_mesh(assemble_gmap(make_block(BlockKind::Hex, 2, 2, 2))),
                    dir / "block.obj");
  const ObjCounts c = count_obj(dir / "block.obj");
  EXPECT_EQ(c.faces, 24u);
  EXPECT_TRUE(c.indices_in_range);
}

TEST(Csv, HeaderNamesTheColumnsAndEveryRowIsOnDiskAtOnce) {
  const auto dir = fresh_folder();
  const auto path = dir / "stats.csv";
  CsvWriter csv(path, {"time", "kinetic_energy", "potential_energy", "tears", "vertices",
                       "elements", "step_ms"});
  EXPECT_EQ(read_lines(path),
            std::vector<std::string>{
                "time,kinetic_energy,potential_energy,tears,vertices,elements,step_ms"});
  csv.write_row({0.0, 0.0, 1.5, 0, 121, 100, 0.25});
  csv.write_row({0.01, 0.125, 1.375, 3, 124, 100, 0.5});
  // Read while the writer is still open: flushed rows are there.
  const auto lines = read_lines(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1], "0,0,1.5,0,121,100,0.25");
  EXPECT_EQ(lines[2], "0.01,0.125,1.375,3,124,100,0.5");
  EXPECT_EQ(csv.rows(), 2u);
  EXPECT_EQ(csv.column_index("tears"), 3u);
  EXPECT_EQ(csv.column_index("nope"), 7u);
}

TEST(Csv, BadRowsAndColumnsAreRejected) {
  const auto dir = fresh_folder();
  CsvWriter csv(dir / "a.csv", {"time", "tears"});
  EXPECT_THROW(csv.write_row({1.0}), std::invalid_argument);
  EXPECT_THROW(CsvWriter(dir / "b.csv", {"time", "time"}), std::invalid_argument);
  EXPECT_THROW(CsvWriter(dir / "c.csv", {}), std::invalid_argument);
}

TEST(Csv, NamesWithCommasAreQuoted) {
  const auto dir = fresh_folder();
  CsvWriter csv(dir / "q.csv", {"time", "energy, total", "say \"hi\""});
  EXPECT_EQ(read_lines(dir / "q.csv")[0], "time,\"energy, total\",\"say \"\"hi\"\"\"");
}

TEST(Csv, UnwritableFolderAndFullDiskAreOutputErrors) {
  const auto dir = fresh_folder();
  try {
    CsvWriter csv(dir / "missing" / "deeper" / "stats.csv", {"time"});
    FAIL() << "no exception";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("stats.csv"), std::string::npos) << e.what();
    EXPECT_EQ(e.error(), std::errc::no_such_file_or_directory);
  }
  if (std::filesystem::exists("/dev/full")) {
    try {
      CsvWriter csv("/dev/full", {"time"});
      FAIL() << "no exception";
    } catch (const OutputError& e) {
      EXPECT_EQ(e.error().value(), ENOSPC) << e.what();
    }
  }
}

}  // namespace
}  // namespace rift
