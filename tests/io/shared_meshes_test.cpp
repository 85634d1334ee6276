// The shared test meshes (../shared/meshes): each is read, assembled and
// checked for validity, and its counts are compared with what the element
// lists, the README of the folder and the geometry say, never with numbers
// printed by rift itself.
#include <gtest/gtest.h>

#include <cmath>

#include "io_test_support.hpp"
#include "shared_test_data.hpp"

namespace rift::test {
namespace {

struct SharedMesh {
  const char* file;
  int dimension;
  std::size_t points;    // from the folder's README (0: not stated)
  std::size_t elements;  // idem
  int euler;             // V - E + F - C: 1 for a disk or a ball, 2 for a sphere
  bool box;              // fills its bounding box (a square or a cube)
};

const SharedMesh kMeshes[] = {
    {"liver.msh", 3, 181, 596, 1, false},     {"liver.obj", 2, 0, 0, 2, false},
    {"cube_low_res.msh", 3, 26, 44, 1, true}, {"msh4_cube.msh", 3, 14, 24, 1, true},
    {"square3.msh", 2, 774, 1450, 1, true},   {"triangleGrid_10_10.obj", 2, 100, 162, 1, true},
    {"cube.mesh", 3, 152, 373, 1, true},
};

Real signed_tet_volume(const MeshData& m, const std::uint32_t* v) {
  const Vec3& a = m.points[v[0]];
  return (m.points[v[1]] - a).cross(m.points[v[2]] - a).dot(m.points[v[3]] - a) / 6;
}

// Area of a polygon in 3D (fan triangulation; the test meshes are planar or
// made of triangles).
Real polygon_area(const MeshData& m, const MeshElement& e) {
  const std::uint32_t* v = m.vertices_of(e);
  Vec3 sum = Vec3::Zero();
  for (std::uint32_t k = 1; k + 1 < e.count; ++k)
    sum += (m.points[v[k]] - m.points[v[0]]).cross(m.points[v[k + 1]] - m.points[v[0]]);
  return sum.norm() / 2;
}

class SharedMeshes : public testing::TestWithParam<SharedMesh> {};

TEST_P(SharedMeshes, CountsMatchTheElementListsAndTheGeometry) {
  const SharedMesh& info = GetParam();
  const std::string path = shared_mesh(info.file);
  RIFT_EXPECT_SHARED_MESHES(!path.empty());
  const MeshData mesh = read_mesh_file(path);
  EXPECT_EQ(mesh.dimension, info.dimension);
  if (info.points > 0) {
    EXPECT_EQ(mesh.points.size(), info.points);
  }
  if (info.elements > 0) {
    EXPECT_EQ(mesh.elements.size(), info.elements);
  }

  AssemblyReport report;
  const GMap map = assemble_gmap(mesh, &report);
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
  const Counts got = counts_of(map);
  EXPECT_EQ(got, expected_counts(mesh));
  EXPECT_EQ(report.nonmanifold_shared, 0u);
  EXPECT_EQ(static_cast<long>(got.vertices) - static_cast<long>(got.edges) +
                static_cast<long>(got.faces) - static_cast<long>(got.volumes),
            info.euler * static_cast<long>(got.components));
  EXPECT_EQ(got.components, 1u);

  if (mesh.dimension == 3) {
    std::size_t negative = 0;
    for (const MeshElement& e : mesh.elements) {
      if (e.type == ElementType::Tetra && signed_tet_volume(mesh, mesh.vertices_of(e)) < 0) {
        ++negative;
      }
    }
    EXPECT_EQ(report.reoriented_solids, negative);
  }
  if (!info.box) return;

  // A mesh that fills its bounding box: the element measures add up to the
  // box's, and the boundary is exactly the sides lying on the box.
  Vec3 lo = mesh.points[0], hi = mesh.points[0];
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 size = hi - lo;
  const Real tol = 1e-6 * size.maxCoeff();
  Real measure = 0;
  for (const MeshElement& e : mesh.elements) {
    measure += mesh.dimension == 3 ? std::abs(signed_tet_volume(mesh, mesh.vertices_of(e)))
                                   : polygon_area(mesh, e);
  }
  Real box = 1;
  for (int c = 0; c < 3; ++c)
    box *= size[c] > tol ? size[c] : 1;
  EXPECT_NEAR(measure, box, 1e-6 * box);

  auto on_box_side = [&](const std::vector<std::uint32_t>& ids) {
    for (int c = 0; c < 3; ++c) {
      if (size[c] <= tol) continue;
      for (const Real plane : {lo[c], hi[c]}) {
        bool all = true;
        for (std::uint32_t id : ids)
          all = all && std::abs(mesh.points[id][c] - plane) < tol;
        if (all) return true;
      }
    }
    return false;
  };
  std::set<std::vector<std::uint32_t>> box_sides;
  for (const MeshElement& e : mesh.elements) {
    const std::uint32_t* v = mesh.vertices_of(e);
    if (mesh.dimension == 2) {
      for (std::uint32_t k = 0; k < e.count; ++k) {
        std::vector<std::uint32_t> side{v[k], v[(k + 1) % e.count]};
        std::sort(side.begin(), side.end());
        if (on_box_side(side)) box_sides.insert(side);
      }
    } else {
      for (const LocalFace& f : element_faces(e.type)) {
        std::vector<std::uint32_t> side;
        for (int k = 0; k < f.count; ++k)
          side.push_back(v[f.v[static_cast<std::size_t>(k)]]);
        std::sort(side.begin(), side.end());
        if (on_box_side(side)) box_sides.insert(side);
      }
    }
  }
  EXPECT_EQ(got.boundary, box_sides.size());
}

INSTANTIATE_TEST_SUITE_P(All, SharedMeshes, testing::ValuesIn(kMeshes),
                         [](const testing::TestParamInfo<SharedMesh>& p) {
                           std::string name = p.param.file;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

// A closed form for the regular grid: n x n points, (n-1)^2 quads each cut in
// two triangles.
TEST(SharedMeshesClosedForm, TriangleGridOfTenByTen) {
  const std::string path = shared_mesh("triangleGrid_10_10.obj");
  RIFT_EXPECT_SHARED_MESHES(!path.empty());
  const std::size_t n = 10, cells = (n - 1) * (n - 1);
  const Counts want{6 * 2 * cells, n * n, 2 * n * (n - 1) + cells, 2 * cells, 0, 1, 4 * (n - 1)};
  EXPECT_EQ(read_counts(path), want);
}

}  // namespace
}  // namespace rift::test
