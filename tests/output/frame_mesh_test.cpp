#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "output_test_support.hpp"
#include "rift/output/frame_mesh.hpp"

namespace rift {
namespace {

using test::quad_cloth;
using test::sewn_dart_on_edge;

std::size_t count_kind(const FrameMesh& f, EdgeKind kind) {
  return static_cast<std::size_t>(
      std::count(f.face_edge_kind.begin(), f.face_edge_kind.end(), kind));
}

std::size_t count_type(const FrameMesh& f, VtkCell type) {
  return static_cast<std::size_t>(std::count(f.cell_types.begin(), f.cell_types.end(), type));
}

std::array<std::int64_t, 8> cell_points(const FrameMesh& f, std::size_t c) {
  std::array<std::int64_t, 8> ids{};
  const std::int64_t begin = c == 0 ? 0 : f.offsets[c - 1];
  for (std::int64_t k = begin; k < f.offsets[c]; ++k)
    ids[static_cast<std::size_t>(k - begin)] = f.connectivity[static_cast<std::size_t>(k)];
  return ids;
}

// (p1 - p0) x (p2 - p0) . (p3 - p0) for four point ids of a cell.
Real triple(const FrameMesh& f, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  const auto p = [&](std::int64_t i) { return f.points[static_cast<std::size_t>(i)]; };
  return (p(b) - p(a)).cross(p(c) - p(a)).dot(p(d) - p(a));
}

TEST(FrameMesh, QuadClothHasOnePointPerVertexAndOneQuadPerFace) {
  GMap map = quad_cloth(4, 3);
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  const FrameMesh f = extract_frame_mesh(map, options);
  EXPECT_EQ(f.dimension, 2);
  EXPECT_EQ(f.point_count(), 20u);
  EXPECT_EQ(f.element_count(), 12u);
  EXPECT_EQ(count_type(f, VtkCell::kQuad), 12u);
  EXPECT_EQ(f.connectivity.size(), 48u);
  EXPECT_EQ(f.offsets.back(), 48);
  EXPECT_EQ(f.face_count(), 12u);
  EXPECT_EQ(f.torn_count(), 0u);
  EXPECT_EQ(f.skipped_elements, 0u);
  for (std::size_t k = 0; k < f.element_count(); ++k)
    EXPECT_EQ(f.element_ids[k], static_cast<std::int64_t>(k));
  // 4x3 cells: 2 * (4 + 3) boundary edges, each seen from its one face.
  EXPECT_EQ(count_kind(f, EdgeKind::kBoundary), 14u);
  EXPECT_EQ(count_kind(f, EdgeKind::kTear), 0u);
  // Every point is the position of its vertex orbit.
  const auto position = map.embedding<Vec3>("position");
  for (std::size_t p = 0; p < f.point_count(); ++p)
    EXPECT_EQ(f.points[p], position[f.point_dart[p]]);
}

TEST(FrameMesh, WithoutOriginalBoundaryEveryFreeEdgeCountsAsTorn) {
  GMap map = quad_cloth(4, 3);
  const FrameMesh f = extract_frame_mesh(map);
  EXPECT_EQ(f.torn_count(), 10u);  // the 12 cells but the two inner ones
  std::size_t by_helper = 0;
  for (Dart d : f.element_dart)
    by_helper += has_free_link(map, d) ? 1 : 0;
  EXPECT_EQ(by_helper, 10u);
}

TEST(FrameMesh, UnsewingAnEdgeFromTheBoundarySplitsAVertex) {
  GMap map = quad_cloth(10, 10);
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  FrameExtractor extractor(options);
  const std::size_t before = extractor.extract(map).point_count();
  EXPECT_EQ(before, 121u);

  const Dart d = sewn_dart_on_edge(map, Vec3(0.5, 0, 0), Vec3(0.5, 0.1, 0));
  ASSERT_NE(d, kNoDart);
  map.unsew(d, 2);
  ASSERT_TRUE(map.is_valid());
  const FrameMesh& f = extractor.extract(map);
  EXPECT_EQ(f.point_count(), before + 1);  // the boundary vertex (0.5, 0) is now two
  EXPECT_EQ(f.torn_count(), 2u);
  EXPECT_EQ(count_kind(f, EdgeKind::kTear), 2u);  // the cut edge, once from each side
  // Both copies sit at the same place until the simulation moves them apart.
  std::size_t at_cut = 0;
  for (const Vec3& p : f.points)
    at_cut += (p - Vec3(0.5, 0, 0)).norm() < 1e-12 ? 1 : 0;
  EXPECT_EQ(at_cut, 2u);
}

TEST(FrameMesh, UnsewingAnInnerEdgeTearsWithoutSplitting) {
  GMap map = quad_cloth(10, 10);
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  const Dart d = sewn_dart_on_edge(map, Vec3(0.5, 0.5, 0), Vec3(0.5, 0.6, 0));
  ASSERT_NE(d, kNoDart);
  map.unsew(d, 2);
  const FrameMesh f = extract_frame_mesh(map, options);
  EXPECT_EQ(f.point_count(), 121u);
  EXPECT_EQ(f.torn_count(), 2u);
}

TEST(FrameMesh, TornDartsTakePrecedence) {
  GMap map = quad_cloth(3, 3);
  std::vector<std::uint8_t> torn_darts(map.capacity(), 0);
  // Flag the free darts of one boundary face as torn.
  const Dart d = sewn_dart_on_edge(map, Vec3(0, 0, 0), Vec3(0, 1.0 / 3, 0));
  EXPECT_EQ(d, kNoDart);  // boundary edges are free, so not found as sewn
  map.for_each_dart([&](Dart x) {
    if (map.is_free(x, 2) && map.embedding<Vec3>("position")[x].norm() < 1e-12) torn_darts[x] = 1;
  });
  FrameOptions options;
  options.torn_darts = torn_darts;
  const FrameMesh f = extract_frame_mesh(map, options);
  EXPECT_EQ(f.torn_count(), 1u);  // only the corner face
}

TEST(FrameMesh, PerElementTornFlagsComeFromAnEmbedding) {
  GMap map = quad_cloth(3, 1);
  auto flag = map.add_embedding<Bool>("was_torn", Orbit::cell(2, 2));
  bool first = true;
  map.for_each_cell(Orbit::cell(2, 2), [&](Dart d) {
    flag[d] = first;
    first = false;
  });
  FrameOptions options;
  options.torn_element = "was_torn";
  const FrameMesh f = extract_frame_mesh(map, options);
  EXPECT_EQ(f.torn, (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_EQ(f.face_torn, f.torn);  // what the renderer tints
  options.torn_element = "position";
  EXPECT_THROW(extract_frame_mesh(map, options), std::invalid_argument);
}

TEST(FrameMesh, TriangleAndMixedGridsGiveTrianglesAndQuads) {
  const FrameMesh tri = extract_frame_mesh(assemble_gmap(make_grid(GridKind::Tri, 3, 2)));
  EXPECT_EQ(count_type(tri, VtkCell::kTriangle), 12u);
  const FrameMesh mix = extract_frame_mesh(assemble_gmap(make_grid(GridKind::Mix, 2, 2)));
  EXPECT_EQ(count_type(mix, VtkCell::kTriangle) + count_type(mix, VtkCell::kQuad),
            mix.element_count());
  EXPECT_GT(count_type(mix, VtkCell::kTriangle), 0u);
  EXPECT_GT(count_type(mix, VtkCell::kQuad), 0u);
}

TEST(FrameMesh, HexBlockGivesVtkHexahedraWithTheirBaseFacingTheTop) {
  GMap map = assemble_gmap(make_block(BlockKind::Hex, 2, 2, 2));
  const FrameMesh f = extract_frame_mesh(map);
  EXPECT_EQ(f.point_count(), 27u);
  EXPECT_EQ(count_type(f, VtkCell::kHexahedron), 8u);
  EXPECT_EQ(f.face_count(), 24u);
  for (std::size_t c = 0; c < f.element_count(); ++c) {
    const auto v = cell_points(f, c);
    // VTK: 0-1-2-3 counter-clockwise seen from the top 4-5-6-7, 4 above 0.
    EXPECT_GT(triple(f, v[0], v[1], v[3], v[4]), 0) << "cell " << c;
    EXPECT_NEAR(
        (f.points[static_cast<std::size_t>(v[4])] - f.points[static_cast<std::size_t>(v[0])])
            .norm(),
        0.5, 1e-12);
    EXPECT_NEAR(
        (f.points[static_cast<std::size_t>(v[6])] - f.points[static_cast<std::size_t>(v[2])])
            .norm(),
        0.5, 1e-12);
  }
}

TEST(FrameMesh, TetBlockGivesPositiveTetrahedraAndItsSurface) {
  GMap map = assemble_gmap(make_block(BlockKind::Tet, 3, 3, 3));
  const FrameMesh f = extract_frame_mesh(map);
  EXPECT_EQ(f.point_count(), 64u);
  EXPECT_EQ(count_type(f, VtkCell::kTetra), 162u);
  EXPECT_EQ(f.face_count(), 6u * 9u * 2u);
  for (std::size_t c = 0; c < f.element_count(); ++c) {
    const auto v = cell_points(f, c);
    EXPECT_GT(triple(f, v[0], v[1], v[2], v[3]), 0) << "cell " << c;
  }
}

TEST(FrameMesh, WedgeAndPyramidFollowVtkOrdering) {
  MeshData mesh;
  mesh.dimension = 3;
  mesh.source = "test";
  mesh.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),    Vec3(0, 0, 1),
                 Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(5, 0, 0),    Vec3(6, 0, 0),
                 Vec3(6, 1, 0), Vec3(5, 1, 0), Vec3(5.5, 0.5, 1)};
  mesh.add_element(ElementType::Wedge, {0, 1, 2, 3, 4, 5});
  mesh.add_element(ElementType::Pyramid, {6, 7, 8, 9, 10});
  const FrameMesh f = extract_frame_mesh(assemble_gmap(mesh));
  ASSERT_EQ(f.element_count(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    const auto v = cell_points(f, c);
    if (f.cell_types[c] == VtkCell::kWedge) {
      // VTK: the base 0-1-2's normal points away from the top 3-4-5.
      EXPECT_LT(triple(f, v[0], v[1], v[2], v[3]), 0);
      for (int k = 0; k < 3; ++k) {
        const Vec3 rise = f.points[static_cast<std::size_t>(v[static_cast<std::size_t>(k + 3)])] -
                          f.points[static_cast<std::size_t>(v[static_cast<std::size_t>(k)])];
        EXPECT_NEAR(rise.norm(), 1.0, 1e-12);
      }
    } else {
      ASSERT_EQ(f.cell_types[c], VtkCell::kPyramid);
      // VTK: the base 0-1-2-3's normal points toward the apex 4.
      EXPECT_GT(triple(f, v[0], v[1], v[3], v[4]), 0);
      EXPECT_EQ(f.points[static_cast<std::size_t>(v[4])], Vec3(5.5, 0.5, 1));
    }
  }
  EXPECT_EQ(f.face_count(), 10u);
}

TEST(FrameMesh, UnsewnFaceInABlockIsACrackWithItsRim) {
  GMap map = assemble_gmap(make_block(BlockKind::Hex, 2, 1, 1));
  const auto boundary = record_boundary_darts(map);
  FrameOptions options;
  options.original_boundary = boundary;
  FrameExtractor extractor(options);
  EXPECT_EQ(extractor.extract(map).face_count(), 10u);
  const Dart d = sewn_dart_on_edge(map, Vec3(0.5, 0, 0), Vec3(0.5, 1, 0));
  ASSERT_NE(d, kNoDart);
  map.unsew(d, 3);
  ASSERT_TRUE(map.is_valid());
  const FrameMesh& f = extractor.extract(map);
  EXPECT_EQ(f.face_count(), 12u);
  EXPECT_EQ(f.point_count(), 16u);  // the four corners of the cut face split
  EXPECT_EQ(f.torn_count(), 2u);
  EXPECT_EQ(std::count(f.face_torn.begin(), f.face_torn.end(), std::uint8_t{1}), 2);
  // The rim: 4 edges seen from both crack faces and from the 4 + 4 side faces.
  EXPECT_EQ(count_kind(f, EdgeKind::kTear), 16u);
}

TEST(FrameMesh, PointArraysComeFromVertexEmbeddings) {
  GMap map = quad_cloth(2, 2);
  const Orbit vertex = vertex_orbit(2);
  auto velocity = map.add_embedding<Vec3>("velocity", vertex);
  auto mass = map.add_embedding<Real>("vertex_mass", vertex);
  map.add_embedding<Real>("corner_mass", Orbit{1});
  const auto position = map.embedding<Vec3>("position");
  map.for_each_dart([&](Dart d) {
    velocity[d] = 2.0 * position[d];
    mass[d] = position[d].x() + 10.0;
  });
  FrameOptions options;
  options.point_arrays = {"velocity", "force", "vertex_mass", "corner_mass", "point_index"};
  const FrameMesh f = extract_frame_mesh(map, options);
  ASSERT_EQ(f.point_data.size(), 3u);  // force is missing, corner_mass is not per vertex
  EXPECT_EQ(f.unsupported_arrays, std::vector<std::string>{"corner_mass"});
  const FrameArray& v = f.point_data[0];
  EXPECT_EQ(v.name, "velocity");
  EXPECT_EQ(v.components, 3);
  ASSERT_EQ(v.reals.size(), 3 * f.point_count());
  for (std::size_t p = 0; p < f.point_count(); ++p) {
    EXPECT_EQ(v.reals[3 * p], 2.0 * f.points[p].x());
    EXPECT_EQ(v.reals[3 * p + 2], 2.0 * f.points[p].z());
  }
  EXPECT_EQ(f.point_data[1].name, "vertex_mass");
  EXPECT_EQ(f.point_data[1].reals[4], f.points[4].x() + 10.0);
  EXPECT_TRUE(f.point_data[2].integral);
}

TEST(FrameMesh, ElementIdsComeFromAnIntEmbedding) {
  GMap map = quad_cloth(2, 1);
  auto ids = map.add_embedding<std::int64_t>("element_id", Orbit::cell(2, 2));
  std::int64_t next = 100;
  map.for_each_cell(Orbit::cell(2, 2), [&](Dart d) { ids[d] = next++; });
  const FrameMesh f = extract_frame_mesh(map);
  EXPECT_EQ(f.element_ids, (std::vector<std::int64_t>{100, 101}));

  GMap wrong = quad_cloth(2, 1);
  wrong.add_embedding<Real>("element_id", Orbit::cell(2, 2));
  EXPECT_THROW(extract_frame_mesh(wrong), std::invalid_argument);
}

TEST(FrameMesh, MissingPositionIsAClearError) {
  GMap map(2);
  try {
    extract_frame_mesh(map);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("position"), std::string::npos);
  }
}

// An octahedron as one volume: 8 triangles, none of the VTK fixed types.
GMap octahedron() {
  const std::vector<Vec3> p = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                               Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  GMap map(3);
  std::vector<int> vertex_of;
  std::vector<int> other_of;
  for (const auto& face : faces) {
    const Dart first = map.create_darts(6);
    for (int i = 0; i < 3; ++i) {
      map.link(first + 2 * i, first + 2 * i + 1, 0);
      map.link(first + 2 * i + 1, first + 2 * ((i + 1) % 3), 1);
      vertex_of.push_back(face[i]);
      other_of.push_back(face[(i + 1) % 3]);
      vertex_of.push_back(face[(i + 1) % 3]);
      other_of.push_back(face[i]);
    }
  }
  for (Dart a = 0; a < vertex_of.size(); ++a) {
    for (Dart b = a + 1; b < vertex_of.size(); ++b) {
      if (a / 6 != b / 6 && vertex_of[a] == vertex_of[b] && other_of[a] == other_of[b]) {
        map.link(a, b, 2);
      }
    }
  }
  auto position = map.add_embedding<Vec3>("position", vertex_orbit(3));
  map.for_each_dart([&](Dart d) { position[d] = p[static_cast<std::size_t>(vertex_of[d])]; });
  return map;
}

TEST(FrameMesh, OtherVolumesArePolyhedraOrSkipped) {
  GMap map = octahedron();
  ASSERT_TRUE(map.is_valid());
  const FrameMesh f = extract_frame_mesh(map);
  ASSERT_EQ(f.element_count(), 1u);
  EXPECT_EQ(f.cell_types[0], VtkCell::kPolyhedron);
  EXPECT_EQ(f.offsets[0], 6);  // the six distinct points
  ASSERT_EQ(f.polyhedron_face_offsets.size(), 1u);
  EXPECT_EQ(f.polyhedron_faces[0], 8);
  EXPECT_EQ(f.polyhedron_face_offsets[0], 1 + 8 * 4);
  EXPECT_EQ(f.face_count(), 8u);

  FrameOptions options;
  options.polyhedra = false;
  const FrameMesh skipped = extract_frame_mesh(map, options);
  EXPECT_EQ(skipped.element_count(), 0u);
  EXPECT_EQ(skipped.skipped_elements, 1u);
  EXPECT_EQ(skipped.face_count(), 8u);  // still rendered
}

TEST(FrameMesh, FacesWithoutPositionsAreSkippedNotRead) {
  GMap map = quad_cloth(2, 2);
  // A triangle built by hand after the embeddings: its darts have no slot yet.
  const Dart first = map.create_darts(6);
  for (Dart i = 0; i < 3; ++i) {
    map.link(first + 2 * i, first + 2 * i + 1, 0);
    map.link(first + 2 * i + 1, first + 2 * ((i + 1) % 3), 1);
  }
  const FrameMesh f = extract_frame_mesh(map);
  EXPECT_EQ(f.element_count(), 4u);
  EXPECT_EQ(f.skipped_elements, 1u);
  EXPECT_EQ(f.point_count(), 9u);
}

TEST(FrameMesh, RemappedFlagsFollowCompaction) {
  const std::vector<std::uint8_t> flags = {1, 0, 1, 1};
  const std::vector<Dart> new_index = {0, kNoDart, 1, 2};
  EXPECT_EQ(remap_dart_flags(flags, new_index), (std::vector<std::uint8_t>{1, 1, 1}));
}

}  // namespace
}  // namespace rift
