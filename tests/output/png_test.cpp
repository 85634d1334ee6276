#include <gtest/gtest.h>
#include <png.h>

#include "output_test_support.hpp"
#include "rift/output/frame_mesh.hpp"
#include "rift/output/output_error.hpp"
#include "rift/output/png_writer.hpp"
#include "rift/output/renderer.hpp"

namespace rift {
namespace {

using test::fresh_folder;

struct Decoded {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

// Decodes with libpng's own reader, independently of the encoder's code.
bool decode(const std::vector<std::uint8_t>& bytes, Decoded& out) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) return false;
  image.format = PNG_FORMAT_RGB;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  return png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr) != 0;
}

std::uint32_t big_endian(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
         (std::uint32_t{b[at + 2]} << 8) | std::uint32_t{b[at + 3]};
}

std::size_t count_pixels(const Image& image, bool (*test)(int r, int g, int b)) {
  std::size_t n = 0;
  for (std::size_t k = 0; k + 2 < image.rgb.size(); k += 3)
    n += test(image.rgb[k], image.rgb[k + 1], image.rgb[k + 2]) ? 1 : 0;
  return n;
}

bool non_background(int r, int g, int b) {
  return r < 250 || g < 250 || b < 250;
}
bool reddish(int r, int g, int b) {
  return r > 140 && r > 2 * g && r > 2 * b;
}

struct Cloth {
  GMap map = test::quad_cloth(10, 10);
  std::vector<std::uint8_t> boundary;
  Cloth() {
    test::bend(map);
    boundary = record_boundary_darts(map);
  }
  FrameMesh frame() const {
    FrameOptions options;
    options.original_boundary = boundary;
    return extract_frame_mesh(map, options);
  }
};

TEST(Png, SignatureSizeAndPixelsSurviveLibpng) {
  Cloth cloth;
  const FrameMesh frame = cloth.frame();
  Renderer renderer;
  const Image& image = renderer.render(frame, renderer.frame_camera(frame));
  ASSERT_EQ(image.width, 800);
  ASSERT_EQ(image.height, 600);
  const std::vector<std::uint8_t> bytes = encode_png(image);
  ASSERT_GT(bytes.size(), 33u);
  const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  EXPECT_TRUE(std::equal(signature, signature + 8, bytes.begin()));
  EXPECT_EQ(std::string(bytes.begin() + 12, bytes.begin() + 16), "IHDR");
  EXPECT_EQ(big_endian(bytes, 16), 800u);
  EXPECT_EQ(big_endian(bytes, 20), 600u);

  Decoded decoded;
  ASSERT_TRUE(decode(bytes, decoded));
  EXPECT_EQ(decoded.width, 800);
  EXPECT_EQ(decoded.height, 600);
  EXPECT_EQ(decoded.rgb, image.rgb);
  // The cloth covers a good part of the picture, and the corners are background.
  EXPECT_GT(count_pixels(image, non_background), 800u * 600u / 10u);
  EXPECT_EQ(image.pixel(0, 0), (std::array<std::uint8_t, 3>{255, 255, 255}));
  EXPECT_EQ(image.pixel(799, 599), (std::array<std::uint8_t, 3>{255, 255, 255}));
}

TEST(Png, TornClothShowsRedWhereTheIntactOneHasNone) {
  Cloth cloth;
  Renderer renderer;
  const FrameMesh intact = cloth.frame();
  const Camera camera = renderer.frame_camera(intact);
  EXPECT_EQ(count_pixels(renderer.render(intact, camera), reddish), 0u);

  // Tear a cut in from the boundary: four edges in a row.
  GMap& map = cloth.map;
  const FrameMesh before = cloth.frame();
  // The bent cloth's points are no longer on the grid, so find edges through point_index:
  // grid point (i, j) has index j * 11 + i.
  const auto index = map.embedding<std::int64_t>("point_index");
  for (int j = 0; j < 4; ++j) {
    map.for_each_dart([&](Dart d) {
      if (!map.is_free(d, 2) && index[d] == j * 11 + 5 &&
          index[map.alpha(d, 0)] == (j + 1) * 11 + 5)
        map.unsew(d, 2);
    });
  }
  ASSERT_TRUE(map.is_valid());
  const FrameMesh torn = cloth.frame();
  EXPECT_GT(torn.point_count(), before.point_count());
  EXPECT_EQ(torn.torn_count(), 8u);
  const Image& image = renderer.render(torn, camera);
  EXPECT_GT(count_pixels(image, reddish), 500u);
}

TEST(Png, SizeIsConfigurable) {
  Cloth cloth;
  RenderOptions options;
  options.width = 320;
  options.height = 200;
  options.supersample = 1;
  Renderer renderer(options);
  const FrameMesh frame = cloth.frame();
  const auto bytes = encode_png(renderer.render(frame, renderer.frame_camera(frame)));
  EXPECT_EQ(big_endian(bytes, 16), 320u);
  EXPECT_EQ(big_endian(bytes, 20), 200u);
  EXPECT_THROW(Renderer(RenderOptions{.width = 0}), std::invalid_argument);
}

TEST(Png, CameraFramesEveryPointOfTheFirstFrame) {
  GMap map = assemble_gmap(make_block(BlockKind::Tet, 3, 3, 3));
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  const FrameMesh frame = extract_frame_mesh(map, options);
  Renderer renderer;
  const Camera camera = renderer.frame_camera(frame);
  Real min_x = 1e9;
  Real max_x = -1e9;
  for (const Vec3& p : frame.points) {
    const ScreenPoint s = camera.project(p, 800, 600);
    EXPECT_GT(s.depth, 0);
    EXPECT_GE(s.x, 0);
    EXPECT_LE(s.x, 800);
    EXPECT_GE(s.y, 0);
    EXPECT_LE(s.y, 600);
    min_x = std::min(min_x, s.x);
    max_x = std::max(max_x, s.x);
  }
  EXPECT_GT(max_x - min_x, 200);  // and fills a sensible part of the image
  const Image& image = renderer.render(frame, camera);
  EXPECT_GT(count_pixels(image, non_background), 800u * 600u / 10u);
  EXPECT_EQ(count_pixels(image, reddish), 0u);
}

TEST(Png, CrackInABlockIsVisible) {
  GMap map = assemble_gmap(make_block(BlockKind::Hex, 4, 4, 4));
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  FrameExtractor extractor(options);
  Renderer renderer;
  const Camera camera = renderer.frame_camera(extractor.extract(map));
  const Image intact = renderer.render(extractor.frame(), camera);
  // Unsew the faces on x = 0.5 for z >= 0.5: a crack from the top down to the middle.
  const auto position = map.embedding<Vec3>("position");
  std::vector<Dart> cut;
  map.for_each_cell(Orbit{0, 1, 3}, [&](Dart d) {
    if (map.is_free(d, 3)) return;
    bool on_plane = true;
    bool upper = true;
    map.for_each_in_orbit(d, Orbit{0, 1}, [&](Dart x) {
      on_plane = on_plane && std::abs(position[x].x() - 0.5) < 1e-9;
      upper = upper && position[x].z() > 0.5 - 1e-9;
    });
    if (on_plane && upper) cut.push_back(d);
  });
  ASSERT_EQ(cut.size(), 8u);
  for (Dart d : cut)
    map.unsew(d, 3);
  const Image& cracked = renderer.render(extractor.extract(map), camera);
  EXPECT_EQ(cracked.width, intact.width);
  std::size_t changed = 0;
  for (std::size_t k = 0; k < intact.rgb.size(); ++k)
    changed += intact.rgb[k] != cracked.rgb[k] ? 1 : 0;
  EXPECT_GT(changed, 200u);  // the crack's rim is drawn on the surface
}

TEST(Png, BlownUpPositionsDoNotBreakTheRenderer) {
  Cloth cloth;
  Renderer renderer;
  const Camera camera = renderer.frame_camera(cloth.frame());
  auto position = cloth.map.embedding<Vec3>("position");
  position.values()[7] = Vec3(std::nan(""), 0, 0);
  position.values()[8] = Vec3(1e300, -1e300, 1e300);
  const FrameMesh frame = cloth.frame();
  EXPECT_GT(count_pixels(renderer.render(frame, camera), non_background), 800u * 600u / 10u);
  // A camera framed on a frame with a NaN still frames the finite points.
  position.values()[8] = Vec3(0.5, 0.5, 0);
  const Camera fresh = renderer.frame_camera(cloth.frame());
  EXPECT_TRUE(fresh.eye().allFinite());
}

TEST(Png, UnwritablePathIsAnOutputError) {
  Image image;
  image.width = 2;
  image.height = 1;
  image.rgb.assign(6, 128);
  const auto dir = fresh_folder();
  write_png(image, dir / "ok.png");
  EXPECT_TRUE(std::filesystem::exists(dir / "ok.png"));
  EXPECT_THROW(write_png(image, dir / "ok.png" / "frame_000000.png"), OutputError);
  image.rgb.pop_back();
  EXPECT_THROW(encode_png(image), std::invalid_argument);
}

}  // namespace
}  // namespace rift
