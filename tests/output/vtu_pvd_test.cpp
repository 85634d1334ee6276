#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <sstream>

#include "output_test_support.hpp"
#include "rift/output/file_sink.hpp"
#include "rift/output/frame_mesh.hpp"
#include "rift/output/output_error.hpp"
#include "rift/output/pvd_writer.hpp"
#include "rift/output/vtu_writer.hpp"

namespace rift {
namespace {

using test::fresh_folder;
using test::quad_cloth;

pugi::xml_node piece_of(const pugi::xml_document& doc) {
  return doc.child("VTKFile").child("UnstructuredGrid").child("Piece");
}

pugi::xml_node array_named(pugi::xml_node parent, const char* name) {
  return parent.find_child_by_attribute("DataArray", "Name", name);
}

template <class T>
std::vector<T> values_of(pugi::xml_node array) {
  std::istringstream in(array.child_value());
  std::vector<T> out;
  for (T v; in >> v;)
    out.push_back(v);
  return out;
}

GMap cloth_with_velocity() {
  GMap map = quad_cloth(4, 3);
  auto velocity = map.add_embedding<Vec3>("velocity", vertex_orbit(2));
  auto force = map.add_embedding<Vec3>("force", vertex_orbit(2));
  const auto position = map.embedding<Vec3>("position");
  map.for_each_dart([&](Dart d) {
    velocity[d] = Vec3(0.1, -0.2, 1.0 / 3.0) + position[d];
    force[d] = Vec3(0, -9.81, 0);
  });
  return map;
}

TEST(Vtu, ClothParsesWithCountsAndArrays) {
  const auto dir = fresh_folder();
  GMap map = cloth_with_velocity();
  const FrameMesh frame = extract_frame_mesh(map);
  VtuWriter writer(VtuEncoding::kAscii);
  writer.write(frame, dir / "cloth.vtu", 0.25);

  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "cloth.vtu").c_str())) << "not XML";
  const pugi::xml_node root = doc.child("VTKFile");
  EXPECT_STREQ(root.attribute("type").value(), "UnstructuredGrid");
  const pugi::xml_node piece = piece_of(doc);
  EXPECT_EQ(piece.attribute("NumberOfPoints").as_int(), 20);
  EXPECT_EQ(piece.attribute("NumberOfCells").as_int(), 12);

  const auto velocity = array_named(piece.child("PointData"), "velocity");
  ASSERT_TRUE(velocity);
  EXPECT_EQ(velocity.attribute("NumberOfComponents").as_int(), 3);
  EXPECT_EQ(values_of<double>(velocity).size(), 60u);
  EXPECT_TRUE(array_named(piece.child("PointData"), "force"));
  EXPECT_TRUE(array_named(piece.child("CellData"), "element_id"));
  const auto torn = array_named(piece.child("CellData"), "torn");
  ASSERT_TRUE(torn);
  EXPECT_EQ(values_of<int>(torn).size(), 12u);

  const auto points = piece.child("Points").child("DataArray");
  EXPECT_EQ(values_of<double>(points).size(), 60u);
  const auto cells = piece.child("Cells");
  EXPECT_EQ(values_of<long>(array_named(cells, "connectivity")).size(), 48u);
  const auto offsets = values_of<long>(array_named(cells, "offsets"));
  ASSERT_EQ(offsets.size(), 12u);
  EXPECT_EQ(offsets.back(), 48);
  for (int type : values_of<int>(array_named(cells, "types")))
    EXPECT_EQ(type, 9);
  const auto time =
      array_named(doc.child("VTKFile").child("UnstructuredGrid").child("FieldData"), "TimeValue");
  EXPECT_DOUBLE_EQ(time.text().as_double(), 0.25);
}

TEST(Vtu, RealsReadBackExactly) {
  const auto dir = fresh_folder();
  GMap map = cloth_with_velocity();
  const FrameMesh frame = extract_frame_mesh(map);
  VtuWriter writer(VtuEncoding::kAscii);
  writer.write(frame, dir / "exact.vtu", 0);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "exact.vtu").c_str()));
  const auto piece = piece_of(doc);
  const auto read = values_of<double>(array_named(piece.child("PointData"), "velocity"));
  ASSERT_EQ(read.size(), frame.point_data[0].reals.size());
  for (std::size_t k = 0; k < read.size(); ++k)
    EXPECT_EQ(read[k], frame.point_data[0].reals[k]) << k;  // 1/3 survives the text round trip
}

TEST(Vtu, TetBlockWritesTetraCells) {
  const auto dir = fresh_folder();
  const FrameMesh frame = extract_frame_mesh(assemble_gmap(make_block(BlockKind::Tet, 2, 2, 2)));
  VtuWriter(VtuEncoding::kAscii).write(frame, dir / "block.vtu", 0);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "block.vtu").c_str()));
  const auto piece = piece_of(doc);
  EXPECT_EQ(piece.attribute("NumberOfPoints").as_int(), 27);
  EXPECT_EQ(piece.attribute("NumberOfCells").as_int(), 48);
  const auto types = values_of<int>(array_named(piece.child("Cells"), "types"));
  EXPECT_EQ(std::count(types.begin(), types.end(), 10), 48);
  EXPECT_FALSE(array_named(piece.child("Cells"), "faces"));  // no polyhedron, no face stream
}

TEST(Vtu, SplitVertexIsOneMorePointInTheFile) {
  const auto dir = fresh_folder();
  GMap map = quad_cloth(10, 10);
  VtuWriter writer(VtuEncoding::kAscii);
  writer.write(extract_frame_mesh(map), dir / "a.vtu", 0);
  const Dart d = test::sewn_dart_on_edge(map, Vec3(0, 0.3, 0), Vec3(0.1, 0.3, 0));
  ASSERT_NE(d, kNoDart);
  map.unsew(d, 2);
  writer.write(extract_frame_mesh(map), dir / "b.vtu", 1);
  pugi::xml_document a;
  pugi::xml_document b;
  ASSERT_TRUE(a.load_file((dir / "a.vtu").c_str()));
  ASSERT_TRUE(b.load_file((dir / "b.vtu").c_str()));
  EXPECT_EQ(piece_of(b).attribute("NumberOfPoints").as_int(),
            piece_of(a).attribute("NumberOfPoints").as_int() + 1);
}

TEST(Vtu, UnwritableFolderIsAnOutputErrorNamingThePath) {
  const auto dir = fresh_folder();
  {
    std::FILE* f = std::fopen((dir / "plain_file").c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fclose(f);
  }
  const auto target = dir / "plain_file" / "frame_000000.vtu";
  try {
    VtuWriter(VtuEncoding::kAscii).write(extract_frame_mesh(quad_cloth(2, 2)), target, 0);
    FAIL() << "no exception";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("plain_file"), std::string::npos) << e.what();
    EXPECT_TRUE(e.error());
  }
  EXPECT_THROW(ensure_directory(dir / "plain_file" / "sub"), OutputError);
}

TEST(Pvd, ListsEveryFrameWrittenSoFarWithItsTime) {
  const auto dir = fresh_folder();
  GMap map = quad_cloth(3, 3);
  PvdWriter pvd(dir / "run.pvd");
  {
    pugi::xml_document empty;
    ASSERT_TRUE(empty.load_file((dir / "run.pvd").c_str()));
    EXPECT_FALSE(empty.child("VTKFile").child("Collection").child("DataSet"));
  }
  VtuWriter vtu(VtuEncoding::kAscii);
  FrameExtractor extractor;
  const double times[] = {0.0, 0.01, 0.02};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string file = frame_file_name("frame_", k, "vtu");
    vtu.write(extractor.extract(map), dir / file, times[k]);
    pvd.add(times[k], file);

    // After every frame the collection on disk is complete: what a crash leaves.
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file((dir / "run.pvd").c_str()));
    std::size_t listed = 0;
    for (const auto& set : doc.child("VTKFile").child("Collection").children("DataSet")) {
      const auto path = dir / set.attribute("file").value();
      ASSERT_TRUE(std::filesystem::exists(path)) << path;
      pugi::xml_document frame;
      EXPECT_TRUE(frame.load_file(path.c_str())) << path;
      EXPECT_EQ(set.attribute("timestep").as_double(), times[listed]);
      ++listed;
    }
    EXPECT_EQ(listed, k + 1);
  }
  EXPECT_EQ(pvd.size(), 3u);
  EXPECT_FALSE(std::filesystem::exists(dir / "run.pvd.tmp"));
}

TEST(Pvd, UnwritableFolderThrowsAtConstruction) {
  EXPECT_THROW(PvdWriter("/proc/rift-no-such-folder/run.pvd"), OutputError);
}

TEST(FileNames, AreZeroPadded) {
  EXPECT_EQ(frame_file_name("frame_", 0, "vtu"), "frame_000000.vtu");
  EXPECT_EQ(frame_file_name("frame_", 42, "png"), "frame_000042.png");
  EXPECT_EQ(frame_file_name("frame_", 1234567, "obj"), "frame_1234567.obj");
}

}  // namespace
}  // namespace rift
