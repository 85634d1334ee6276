#include <gtest/gtest.h>

#include <pugixml.hpp>

#include "output_test_support.hpp"
#include "rift/io/read_mesh.hpp"
#include "rift/output/frame_outputs.hpp"
#include "rift/output/output_error.hpp"

namespace rift {
namespace {

using test::fresh_folder;

TEST(FrameOutputs, WritesTheSeriesTheRendersAndTheStatistics) {
  const auto dir = fresh_folder() / "cloth";  // created by FrameOutputs
  OutputConfig config;
  config.directory = dir;
  config.name = "cloth";
  config.obj = true;
  config.png_every = 2;
  config.render.width = 200;
  config.render.height = 150;
  config.csv_columns = {"time", "tears", "vertices"};
  FrameOutputs out(config);
  EXPECT_TRUE(std::filesystem::exists(dir / "cloth.pvd"));

  GMap map = test::quad_cloth(6, 6);
  test::bend(map);
  const auto index = map.embedding<std::int64_t>("point_index");
  for (int frame = 0; frame < 3; ++frame) {
    if (frame == 2) {
      map.for_each_dart([&](Dart d) {
        if (!map.is_free(d, 2) && index[d] == 3 && index[map.alpha(d, 0)] == 10) map.unsew(d, 2);
      });
    }
    const FrameMesh& f = out.write_frame(map, 0.1 * frame);
    out.write_statistics(std::vector<double>{0.1 * frame, static_cast<double>(f.torn_count()),
                                             static_cast<double>(f.point_count())});
  }
  EXPECT_EQ(out.frames_written(), 3u);
  ASSERT_TRUE(out.camera().has_value());

  pugi::xml_document pvd;
  ASSERT_TRUE(pvd.load_file((dir / "cloth.pvd").c_str()));
  std::vector<std::string> files;
  for (const auto& set : pvd.child("VTKFile").child("Collection").children("DataSet"))
    files.push_back(set.attribute("file").value());
  EXPECT_EQ(files,
            (std::vector<std::string>{"frame_000000.vtu", "frame_000001.vtu", "frame_000002.vtu"}));
  for (const auto& file : files) {
    EXPECT_NO_THROW(read_mesh_file((dir / file).string())) << file;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_000002.obj"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_000000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_000001.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_000002.png"));

  // The first frame's boundary is the original one: only the cut counts as torn.
  const auto csv = test::read_lines(dir / "cloth.csv");
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_EQ(csv[0], "time,tears,vertices");
  EXPECT_EQ(csv[1], "0,0,49");
  EXPECT_EQ(csv[3], "0.2,2,50");
}

TEST(FrameOutputs, UnwritableFolderFailsAtOnce) {
  const auto dir = fresh_folder();
  {
    std::FILE* f = std::fopen((dir / "file").c_str(), "w");
    std::fclose(f);
  }
  OutputConfig config;
  config.directory = dir / "file" / "out";
  EXPECT_THROW(FrameOutputs out(config), OutputError);
}

}  // namespace
}  // namespace rift
