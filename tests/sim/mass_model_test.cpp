#include "rift/sim/mass_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "jittered_mesh.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"

namespace rift {
namespace {

Real sum_vertex_masses(const GMap& map, const Embedding<Real>& vertex_mass) {
  Real total = 0;
  map.for_each_cell(Orbit::cell(0, map.dimension()), [&](Dart v) { total += vertex_mass[v]; });
  return total;
}

// Unsews the first element from its neighbours: its vertices split.
void unsew_first_element(GMap& map) {
  const int n = map.dimension();
  std::vector<Dart> inner;
  map.for_each_in_orbit(0, element_orbit(n), [&](Dart d) { inner.push_back(d); });
  for (Dart d : inner) {
    if (!map.is_free(d, n)) map.unsew(d, n);
  }
}

TEST(MassModel, ElementMeasures) {
  for (const char* spec : {"grid:quad:4x3", "grid:tri:4x3", "grid:mix:5x5"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    auto pos = map.embedding<Vec3>("position");
    Real area = 0;
    map.for_each_cell(element_orbit(2), [&](Dart e) { area += element_measure(map, e, pos); });
    EXPECT_NEAR(area, 1.0, 1e-12) << spec;  // the unit square
  }
  for (const char* spec : {"block:hex:2x3x2", "block:tet:2x2x3"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    auto pos = map.embedding<Vec3>("position");
    Real volume = 0;
    map.for_each_cell(element_orbit(3), [&](Dart e) { volume += element_measure(map, e, pos); });
    EXPECT_NEAR(volume, 1.0, 1e-12) << spec;  // the unit cube
  }
}

TEST(MassModel, TotalMassEqualsSumOfVertexMassesBeforeAndAfterSplits) {
  for (const char* spec : {"grid:mix:6x4", "block:tet:2x2x2", "block:hex:2x2x1"}) {
    GMap map = assemble_gmap(make_generated_mesh(spec));
    const int n = map.dimension();
    auto pos = map.embedding<Vec3>("position");
    auto corner = map.add_embedding<Real>("corner_mass", corner_orbit(n));
    auto vertex = map.add_embedding<Real>("vertex_mass", Orbit::cell(0, n), MergePolicy::kSum);
    const Real total = assign_corner_masses_by_total(map, 0.1, corner, pos);
    EXPECT_NEAR(total, 0.1, 1e-15);
    update_all_vertex_masses(map, corner, vertex);
    EXPECT_NEAR(sum_vertex_masses(map, vertex), 0.1, 1e-12) << spec;
    // Cut every inner n-link of the first element: its vertices split, and
    // the split vertices' masses must be recomputed from their corners.
    std::vector<Dart> touched;
    map.for_each_in_orbit(0, element_orbit(n), [&](Dart d) {
      touched.push_back(d);
      touched.push_back(map.alpha(d, n));
    });
    for (Dart d : touched) {
      if (!map.is_free(d, n)) map.unsew(d, n);
    }
    ASSERT_TRUE(map.is_valid());
    for (Dart d : touched)
      update_vertex_mass(map, d, corner, vertex);
    EXPECT_NEAR(sum_vertex_masses(map, vertex), 0.1, 1e-12) << spec;
  }
}

// The whole-map pass (one pass over the darts) gives every vertex the sum of
// its corners' masses, as the walk of update_vertex_mass does, on meshes
// whose elements all differ (jittered points) and after vertices were split.
TEST(MassModel, AllVertexMassesAreEachVertexsCornerSums) {
  for (const char* spec : {"grid:mix:7x5", "block:tet:3x2x2", "block:hex:3x3x2"}) {
    for (bool split : {false, true}) {
      GMap map = assemble_gmap(make_generated_mesh(spec));
      const int n = map.dimension();
      test::jitter_vertices(map, 5, 0.1);
      auto pos = map.embedding<Vec3>("position");
      if (split) {
        unsew_first_element(map);
        ASSERT_TRUE(map.is_valid());
      }
      // From the elements' masses before corners hold slots: the pass then
      // finds each corner's first dart by a walk (3D) or by its 1-neighbour
      // (2D), and must give the bits of the pass over corner slots below.
      auto from_elements =
          map.add_embedding<Real>("from_elements", Orbit::cell(0, n), MergePolicy::kSum);
      ASSERT_EQ(map.slotted_attachment(corner_orbit(n)), nullptr) << spec;
      vertex_masses_from_elements(map, element_masses_by_total(map, 2.0, pos), from_elements);
      auto corner = map.add_embedding<Real>("corner_mass", corner_orbit(n));
      auto all = map.add_embedding<Real>("vertex_mass", Orbit::cell(0, n), MergePolicy::kSum);
      auto each = map.add_embedding<Real>("walked_mass", Orbit::cell(0, n), MergePolicy::kSum);
      assign_corner_masses_by_total(map, 2.0, corner, pos);
      update_all_vertex_masses(map, corner, all);
      std::size_t vertices = 0;
      std::vector<Real> masses;
      map.for_each_cell(Orbit::cell(0, n), [&](Dart v) {
        update_vertex_mass(map, v, corner, each);
        EXPECT_NEAR(all[v], each[v], 1e-15 * each[v]) << spec << " vertex dart " << v;
        EXPECT_EQ(all[v], from_elements[v]) << spec << " vertex dart " << v;
        EXPECT_GT(all[v], 0.0);
        masses.push_back(all[v]);
        ++vertices;
      });
      EXPECT_NEAR(sum_vertex_masses(map, all), 2.0, 1e-12) << spec;
      // The masses differ from vertex to vertex (a pass writing one value
      // everywhere would not).
      EXPECT_GT(*std::max_element(masses.begin(), masses.end()),
                1.01 * *std::min_element(masses.begin(), masses.end()));
      EXPECT_GT(vertices, 10u);
    }
  }
}

// A vertex's mass from the darts its walk listed (what a tear's update
// passes) is the walk's sum, bit for bit: every corner once, in the walk's
// order. Meshes whose elements all differ, split or not, and a fan of 40
// triangles around one vertex, more corners than the list keeps, which
// falls back to the walk.
MeshData fan_of_triangles(int count) {
  MeshData mesh;
  mesh.dimension = 2;
  mesh.points.push_back(Vec3::Zero());
  for (int k = 0; k < count; ++k) {
    const Real a = 2 * 3.141592653589793 * k / count;
    // Uneven radii: every triangle's area, hence every corner's mass, differs.
    const Real r = 1 + 0.01 * k;
    mesh.points.push_back(Vec3(r * std::cos(a), r * std::sin(a), 0));
  }
  for (int k = 0; k < count; ++k) {
    const auto next = static_cast<std::uint32_t>(1 + (k + 1) % count);
    mesh.add_element(ElementType::Polygon, {0u, static_cast<std::uint32_t>(1 + k), next});
  }
  return mesh;
}

TEST(MassModel, AVertexsWalkedDartsGiveTheWalksSum) {
  for (const char* spec : {"grid:mix:7x5", "block:tet:3x2x2", "block:hex:3x3x2", "fan"}) {
    for (bool split : {false, true}) {
      GMap map = assemble_gmap(std::string(spec) == "fan" ? fan_of_triangles(40)
                                                          : make_generated_mesh(spec));
      const int n = map.dimension();
      test::jitter_vertices(map, 7, 0.1);
      if (split) {
        unsew_first_element(map);
        ASSERT_TRUE(map.is_valid());
      }
      auto pos = map.embedding<Vec3>("position");
      auto corner = map.add_embedding<Real>("corner_mass", corner_orbit(n));
      auto walked = map.add_embedding<Real>("walked_mass", Orbit::cell(0, n), MergePolicy::kSum);
      auto listed = map.add_embedding<Real>("listed_mass", Orbit::cell(0, n), MergePolicy::kSum);
      assign_corner_masses_by_total(map, 2.0, corner, pos);
      std::size_t largest = 0;
      // From every dart of each vertex, not only its first: each start is
      // its own walk order.
      map.for_each_dart([&](Dart d) {
        std::vector<Dart> darts;
        map.for_each_in_orbit(d, Orbit::cell(0, n), [&](Dart x) { darts.push_back(x); });
        largest = std::max(largest, darts.size());
        update_vertex_mass(map, d, corner, walked);
        listed[d] = -1;
        update_vertex_mass(map, darts, corner, listed);
        EXPECT_EQ(listed[d], walked[d]) << spec << " dart " << d;
        EXPECT_GT(listed[d], 0.0) << spec << " dart " << d;
      });
      if (std::string(spec) == "fan") {
        EXPECT_GE(largest, 78u);  // 39 or 40 corners of 2 darts: past the list
      }
    }
  }
}

TEST(MassModel, CornerMassesSplitEachElementEqually) {
  GMap map = assemble_gmap(make_grid(GridKind::Mix, 2, 1));
  auto pos = map.embedding<Vec3>("position");
  auto corner = map.add_embedding<Real>("corner_mass", corner_orbit(2));
  assign_corner_masses_by_density(map, 2.0, corner, pos);
  // Quad of area 0.5 (4 corners) and two triangles of area 0.25 (3 corners).
  map.for_each_cell(element_orbit(2), [&](Dart e) {
    int corners = 0;
    map.for_each_sub_orbit(e, element_orbit(2), corner_orbit(2), [&](Dart) { ++corners; });
    const Real expected = corners == 4 ? 2.0 * 0.5 / 4 : 2.0 * 0.25 / 3;
    map.for_each_in_orbit(e, element_orbit(2),
                          [&](Dart d) { EXPECT_NEAR(corner[d], expected, 1e-15); });
  });
}

}  // namespace
}  // namespace rift
