// Maps, folders and file readers shared by the output writer tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"

namespace rift::test {

/// A fresh, empty folder named after the running test.
inline std::filesystem::path fresh_folder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rift_output_tests" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::vector<std::string> read_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

inline GMap quad_cloth(int nx, int ny) {
  return assemble_gmap(make_grid(GridKind::Quad, nx, ny));
}

/// Bends a cloth in [0,1]^2 into a 3D arc, so that renders show shading.
inline void bend(GMap& map) {
  auto position = map.embedding<Vec3>("position");
  for (Vec3& p : position.values()) {
    const Real angle = (p.x() - 0.5) * 2.2;
    p = Vec3(0.8 * std::sin(angle), p.y(), 0.8 * (std::cos(angle) - 1.0) + 0.15 * p.y() * p.y());
  }
}

/// A dart at `from` on the edge to `to` that is sewn (not 2-free in 2D, not
/// 3-free in 3D), or kNoDart.
inline Dart sewn_dart_on_edge(const GMap& map, const Vec3& from, const Vec3& to) {
  const auto position = map.embedding<Vec3>("position");
  Dart found = kNoDart;
  map.for_each_dart([&](Dart d) {
    if (found != kNoDart || map.is_free(d, map.dimension())) return;
    if ((position[d] - from).norm() < 1e-9 && (position[map.alpha(d, 0)] - to).norm() < 1e-9) {
      found = d;
    }
  });
  return found;
}

}  // namespace rift::test
