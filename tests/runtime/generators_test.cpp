// Closed-form cell counts for every builder.
#include <gtest/gtest.h>

#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/mesh/map_statistics.hpp"

namespace rift {
namespace {

using Counts = MapStatistics;

MapStatistics stats_of(const MeshData& mesh) {
  GMap map = assemble_gmap(mesh);
  const auto problems = map.check_validity();
  EXPECT_TRUE(problems.empty()) << mesh.source << ": " << problems.front();
  return compute_statistics(map);
}

class GridCounts : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(GridCounts, QuadTriAndMixMatchTheirFormulas) {
  const auto [nx, ny] = GetParam();
  const std::size_t cells = static_cast<std::size_t>(nx) * ny;
  const std::size_t vertices = static_cast<std::size_t>(nx + 1) * (ny + 1);
  const std::size_t grid_edges = static_cast<std::size_t>(nx) * (ny + 1) + ny * (nx + 1);
  const std::size_t boundary = 2 * static_cast<std::size_t>(nx + ny);
  // Mix splits the quads with i + j even: ceil(cells / 2) of them when one
  // of nx, ny is even; otherwise (cells + 1) / 2 as well.
  std::size_t split = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i)
      split += (i + j) % 2 == 0;
  }

  const MapStatistics q = stats_of(make_grid(GridKind::Quad, nx, ny));
  EXPECT_EQ(q.darts, 8 * cells);
  EXPECT_EQ(q.vertices, vertices);
  EXPECT_EQ(q.edges, grid_edges);
  EXPECT_EQ(q.faces, cells);
  EXPECT_EQ(q.components, 1u);
  EXPECT_EQ(q.boundary, boundary);

  const MapStatistics t = stats_of(make_grid(GridKind::Tri, nx, ny));
  EXPECT_EQ(t.darts, 12 * cells);
  EXPECT_EQ(t.vertices, vertices);
  EXPECT_EQ(t.edges, grid_edges + cells);
  EXPECT_EQ(t.faces, 2 * cells);
  EXPECT_EQ(t.boundary, boundary);

  const MapStatistics m = stats_of(make_grid(GridKind::Mix, nx, ny));
  EXPECT_EQ(m.darts, 8 * (cells - split) + 12 * split);
  EXPECT_EQ(m.vertices, vertices);
  EXPECT_EQ(m.edges, grid_edges + split);
  EXPECT_EQ(m.faces, cells + split);
  EXPECT_EQ(m.boundary, boundary);
  EXPECT_EQ(split, (cells + 1) / 2);
  // Euler characteristic of a disc.
  for (const MapStatistics& s : {q, t, m}) {
    EXPECT_EQ(
        static_cast<long>(s.vertices) - static_cast<long>(s.edges) + static_cast<long>(s.faces), 1);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, GridCounts,
                         ::testing::Values(std::pair{1, 1}, std::pair{2, 3}, std::pair{10, 10},
                                           std::pair{7, 4}, std::pair{1, 9}));

class BlockCounts : public ::testing::TestWithParam<std::tuple<int, int, int>> {};

TEST_P(BlockCounts, HexAndTetMatchTheirFormulas) {
  const auto [nx, ny, nz] = GetParam();
  const std::size_t x = nx, y = ny, z = nz;
  const std::size_t cubes = x * y * z;
  const std::size_t vertices = (x + 1) * (y + 1) * (z + 1);
  const std::size_t axis_edges =
      x * (y + 1) * (z + 1) + y * (x + 1) * (z + 1) + z * (x + 1) * (y + 1);
  const std::size_t squares = x * y * (z + 1) + y * z * (x + 1) + z * x * (y + 1);
  const std::size_t boundary_squares = 2 * (x * y + y * z + z * x);

  const MapStatistics h = stats_of(make_block(BlockKind::Hex, nx, ny, nz));
  EXPECT_EQ(h.darts, 48 * cubes);
  EXPECT_EQ(h.vertices, vertices);
  EXPECT_EQ(h.edges, axis_edges);
  EXPECT_EQ(h.faces, squares);
  EXPECT_EQ(h.volumes, cubes);
  EXPECT_EQ(h.components, 1u);
  EXPECT_EQ(h.boundary, boundary_squares);

  // Kuhn: every square gets one diagonal, every cube one body diagonal; each
  // square is two triangles and each cube has six inner triangles.
  const MapStatistics t = stats_of(make_block(BlockKind::Tet, nx, ny, nz));
  EXPECT_EQ(t.darts, 24 * 6 * cubes);
  EXPECT_EQ(t.vertices, vertices);
  EXPECT_EQ(t.edges, axis_edges + squares + cubes);
  EXPECT_EQ(t.faces, 2 * squares + 6 * cubes);
  EXPECT_EQ(t.volumes, 6 * cubes);
  EXPECT_EQ(t.boundary, 2 * boundary_squares);
  for (const MapStatistics& s : {h, t}) {
    EXPECT_EQ(static_cast<long>(s.vertices) - static_cast<long>(s.edges) +
                  static_cast<long>(s.faces) - static_cast<long>(s.volumes),
              1);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, BlockCounts,
                         ::testing::Values(std::tuple{1, 1, 1}, std::tuple{2, 3, 4},
                                           std::tuple{4, 4, 4}, std::tuple{5, 1, 2}));

TEST(Generators, TetBlockIsPositivelyOriented) {
  AssemblyReport report;
  assemble_gmap(make_block(BlockKind::Tet, 3, 2, 2), &report);
  EXPECT_EQ(report.reoriented_solids, 0u);
  EXPECT_EQ(report.flat_elements, 0u);
}

TEST(Generators, SpellingsAndTheirErrors) {
  EXPECT_EQ(make_generated_mesh("grid:quad:3x2").elements.size(), 6u);
  EXPECT_EQ(make_generated_mesh("block:tet:1x1x2").elements.size(), 12u);
  auto message = [](const char* spec) {
    try {
      make_generated_mesh(spec);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("grid:hex:3x3").find("unknown grid kind 'hex'"), std::string::npos);
  EXPECT_NE(message("grid:quad:3").find("expected 2 cell counts"), std::string::npos);
  EXPECT_NE(message("grid:quad:3x0").find("at least 1"), std::string::npos);
  EXPECT_NE(message("grid:quad:3y3").find("unexpected 'y'"), std::string::npos);
  EXPECT_NE(message("block:tet:1x1").find("expected 3 cell counts"), std::string::npos);
  EXPECT_NE(message("block:tet:100000x100000x100").find("too many cells"), std::string::npos);
  EXPECT_NE(message("sphere:1").find("not a generator spelling"), std::string::npos);
  EXPECT_TRUE(is_generator_spec("grid:quad:1x1"));
  EXPECT_FALSE(is_generator_spec("mesh.obj"));
}

}  // namespace
}  // namespace rift
