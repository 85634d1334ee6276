// The same meshes built by rift (assemble_gmap) and, independently, in CGAL's
// Generalized_map: equal cell counts, both valid, and an explicit isomorphism
// between the two maps that keeps every dart's vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "cgal_mirror.hpp"
#include "rift/io/read_mesh.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/mesh/map_statistics.hpp"
#include "shared_test_data.hpp"

namespace {

using rift_cgal::CgalMirror;
using rift_cgal::Counts;

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines)
    text += line + "\n";
  return text;
}

template <unsigned N>
void expect_same_map(const rift::MeshData& mesh) {
  rift::AssemblyReport report;
  const rift::GMap map = rift::assemble_gmap(mesh, &report);
  CgalMirror<N> mirror(mesh);
  EXPECT_TRUE(mirror.errors().empty()) << join(mirror.errors());

  const Counts ours = rift_cgal::rift_counts(map);
  const Counts theirs = mirror.counts();
  EXPECT_TRUE(ours.valid) << join(map.check_validity());
  EXPECT_TRUE(theirs.valid);
  EXPECT_EQ(ours, theirs) << "rift: " << to_string(ours) << "\nCGAL: " << to_string(theirs);
  EXPECT_EQ(report.nonmanifold_shared, mirror.nonmanifold_shared());

  // What `rift info` prints must be the same figures.
  const rift::MapStatistics stats = rift::compute_statistics(map);
  EXPECT_EQ(stats.darts, theirs.darts);
  EXPECT_EQ(stats.vertices, theirs.vertices);
  EXPECT_EQ(stats.edges, theirs.edges);
  EXPECT_EQ(stats.faces, theirs.faces);
  EXPECT_EQ(stats.volumes, theirs.volumes);
  EXPECT_EQ(stats.components, theirs.components);
  EXPECT_EQ(stats.boundary, theirs.boundary);

  std::vector<std::uint32_t> rift_to_cgal;
  EXPECT_EQ(mirror.match_darts(map, rift_to_cgal), "");
}

void expect_same_map(const rift::MeshData& mesh) {
  if (mesh.dimension == 2) {
    expect_same_map<2>(mesh);
  } else {
    ASSERT_EQ(mesh.dimension, 3);
    expect_same_map<3>(mesh);
  }
}

std::string test_name(std::string spec) {
  std::replace_if(
      spec.begin(), spec.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
      '_');
  return spec;
}

// ---- generated meshes -------------------------------------------------------------

class GeneratedMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(GeneratedMesh, SameMapAsCgal) {
  expect_same_map(rift::make_generated_mesh(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(
    Builders, GeneratedMesh,
    ::testing::Values("grid:quad:1x1", "grid:quad:1x7", "grid:quad:5x3", "grid:quad:16x16",
                      "grid:tri:1x1", "grid:tri:7x1", "grid:tri:4x6", "grid:tri:12x12",
                      "grid:mix:1x1", "grid:mix:2x1", "grid:mix:3x5", "grid:mix:11x11",
                      "block:hex:1x1x1", "block:hex:3x1x1", "block:hex:2x3x4", "block:hex:5x5x5",
                      "block:tet:1x1x1", "block:tet:1x1x3", "block:tet:3x2x2", "block:tet:4x4x4"),
    [](const ::testing::TestParamInfo<std::string>& param) { return test_name(param.param); });

// The builders called directly, not through the spelling parser.
TEST(GeneratedMeshDirect, GridsAndBlocksMatchCgal) {
  expect_same_map(rift::make_grid(rift::GridKind::Quad, 9, 2));
  expect_same_map(rift::make_grid(rift::GridKind::Tri, 2, 9));
  expect_same_map(rift::make_grid(rift::GridKind::Mix, 6, 7));
  expect_same_map(rift::make_block(rift::BlockKind::Hex, 1, 4, 2));
  expect_same_map(rift::make_block(rift::BlockKind::Tet, 2, 1, 3));
}

// ---- hand-made meshes: non-manifold and mixed solids --------------------------------

TEST(HandMadeMesh, ThreeTrianglesOnOneEdge) {
  rift::MeshData mesh;
  mesh.dimension = 2;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  mesh.add_element(rift::ElementType::Polygon, {0, 1, 2});
  mesh.add_element(rift::ElementType::Polygon, {1, 0, 3});
  mesh.add_element(rift::ElementType::Polygon, {0, 1, 4});
  expect_same_map(mesh);
}

TEST(HandMadeMesh, BowTieVertexIsTwoVertices) {
  rift::MeshData mesh;
  mesh.dimension = 2;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  mesh.add_element(rift::ElementType::Polygon, {0, 1, 2});
  mesh.add_element(rift::ElementType::Polygon, {0, 3, 4});
  expect_same_map(mesh);
}

TEST(HandMadeMesh, PolygonsOfManySides) {
  rift::MeshData mesh;
  mesh.dimension = 2;
  for (int i = 0; i < 8; ++i)
    mesh.points.emplace_back(i, i % 3, 0);
  mesh.add_element(rift::ElementType::Polygon, {0, 1, 2, 3, 4});
  mesh.add_element(rift::ElementType::Polygon, {4, 3, 5, 6, 7});
  mesh.add_element(rift::ElementType::Polygon, {2, 1, 6, 5});
  expect_same_map(mesh);
}

TEST(HandMadeMesh, MixedSolidsShareFaces) {
  rift::MeshData mesh;
  mesh.dimension = 3;
  // A unit cube (0-7), a wedge on its top (8, 9 ridge), a pyramid in front
  // (apex 10) and a tetrahedron on the wedge's end triangle (apex 11).
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},   {0, 1, 0},   {0, 0, 1},      {1, 0, 1},
                 {1, 1, 1}, {0, 1, 1}, {0.5, 0, 2}, {0.5, 1, 2}, {0.5, -1, 0.5}, {0.5, 2, 2}};
  mesh.add_element(rift::ElementType::Hexa, {0, 1, 2, 3, 4, 5, 6, 7});
  mesh.add_element(rift::ElementType::Wedge, {4, 5, 8, 7, 6, 9});
  mesh.add_element(rift::ElementType::Pyramid, {0, 1, 5, 4, 10});
  mesh.add_element(rift::ElementType::Tetra, {7, 6, 9, 11});
  expect_same_map(mesh);
}

TEST(HandMadeMesh, InvertedTetrahedraAreTheSameTopology) {
  rift::MeshData mesh;
  mesh.dimension = 3;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.add_element(rift::ElementType::Tetra, {0, 2, 1, 3});  // negative orientation
  mesh.add_element(rift::ElementType::Tetra, {0, 1, 2, 4});  // negative too
  expect_same_map(mesh);
}

// ---- the shared meshes ----------------------------------------------------------

std::vector<std::string> shared_mesh_files() {
  namespace fs = std::filesystem;
  std::vector<std::string> names;
  std::error_code ec;
  const fs::path dir(RIFT_SHARED_MESHES);
  if (!fs::is_directory(dir, ec)) return names;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".obj" || ext == ".msh" || ext == ".mesh" || ext == ".vtu" || ext == ".vtk") {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

class SharedMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedMesh, SameMapAsCgal) {
  const std::string path = std::string(RIFT_SHARED_MESHES) + "/" + GetParam();
  rift::MeshData mesh;
  try {
    mesh = rift::read_mesh_file(path);
  } catch (const std::exception& e) {
    FAIL() << "reading failed: " << e.what();
  }
  expect_same_map(mesh);
}

INSTANTIATE_TEST_SUITE_P(Files, SharedMesh, ::testing::ValuesIn(shared_mesh_files()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return test_name(param.param);
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SharedMesh);

// The cross-checks above are instantiated from the folder's listing, so an
// empty or missing folder would run none of them: this test is what fails then.
TEST(SharedMeshFolder, Present) {
  RIFT_EXPECT_SHARED_MESHES(std::filesystem::is_directory(RIFT_SHARED_MESHES));
  const std::vector<std::string> files = shared_mesh_files();
  for (const char* expected : {"cube.mesh", "cube_low_res.msh", "liver.msh", "liver.obj",
                               "msh4_cube.msh", "square3.msh", "triangleGrid_10_10.obj"}) {
    EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected;
  }
}

}  // namespace
