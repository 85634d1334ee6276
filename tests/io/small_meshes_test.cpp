// Every hand-made shape in every format: read, assemble, check validity and
// compare the counts with the ones worked out by hand, and with the counts
// derived from the element lists.
#include <gtest/gtest.h>

#include "io_test_support.hpp"
#include "shapes.hpp"

namespace rift::test {
namespace {

struct Format {
  const char* extension;
  std::string (*write)(const Shape&);
  bool pyramids;  // Medit has no pyramid keyword rift reads
};

const Format kFormats[] = {
    {"obj", to_obj, true},
    {"msh", [](const Shape& s) { return to_gmsh12(s, 1); }, true},
    {"msh", [](const Shape& s) { return to_gmsh12(s, 2); }, true},
    {"msh", to_gmsh41, true},
    {"mesh", to_medit, false},
    {"vtk", [](const Shape& s) { return to_vtk(s, false); }, true},
    {"vtk", [](const Shape& s) { return to_vtk(s, true); }, true},
    {"vtu", to_vtu, true},
};

bool has(const Shape& s, ElementType t) {
  for (const ShapeElement& e : s.elements) {
    if (e.type == t) return true;
  }
  return false;
}

TEST(SmallMeshes, EveryShapeInEveryFormatHasItsHandCounts) {
  int variant = 0;
  for (const Format& format : kFormats) {
    ++variant;
    for (const Shape& shape : shapes()) {
      if (std::string(format.extension) == "obj" && shape.dimension == 3) continue;
      if (!format.pyramids && has(shape, ElementType::Pyramid)) continue;
      const std::string name = shape.name + "_" + std::to_string(variant) + "." + format.extension;
      SCOPED_TRACE(name);
      const std::string path = write_temp(name, format.write(shape));
      const MeshData mesh = read_mesh_file(path);
      EXPECT_EQ(mesh.dimension, shape.dimension);
      ASSERT_EQ(mesh.points.size(), shape.points.size());
      ASSERT_EQ(mesh.elements.size(), shape.elements.size());
      EXPECT_EQ(expected_counts(mesh), shape.expected);
      AssemblyReport report;
      const GMap map = assemble_gmap(mesh, &report);
      EXPECT_EQ(map.check_validity(), std::vector<std::string>{});
      EXPECT_EQ(counts_of(map), shape.expected);
      EXPECT_EQ(report.reoriented_solids, 0u);
      EXPECT_EQ(report.nonmanifold_shared, 0u);
    }
  }
}

// Each element read has the corners of one written element, in the same
// order, at the written positions: vertex ids were mapped back to the right
// points. (Medit groups elements by kind, so file order is not shape order.)
TEST(SmallMeshes, ElementCornersKeepTheirPositions) {
  int variant = 0;
  for (const Format& format : kFormats) {
    ++variant;
    for (const Shape& shape : shapes()) {
      if (std::string(format.extension) == "obj" && shape.dimension == 3) continue;
      if (!format.pyramids && has(shape, ElementType::Pyramid)) continue;
      const std::string name = shape.name + "_" + std::to_string(variant) + "." + format.extension;
      SCOPED_TRACE(name);
      const MeshData mesh = read_mesh_file(write_temp(name, format.write(shape)));
      ASSERT_EQ(mesh.elements.size(), shape.elements.size());
      std::vector<bool> matched(shape.elements.size(), false);
      for (const MeshElement& el : mesh.elements) {
        EXPECT_GT(el.source_line, 0);
        bool found = false;
        for (std::size_t s = 0; s < shape.elements.size() && !found; ++s) {
          const ShapeElement& want = shape.elements[s];
          if (matched[s] || want.type != el.type || want.v.size() != el.count) continue;
          bool same = true;
          for (std::uint32_t k = 0; k < el.count; ++k)
            same = same && mesh.points[mesh.vertices_of(el)[k]] == shape.points[want.v[k]];
          found = matched[s] = same;
        }
        EXPECT_TRUE(found) << "element on line " << el.source_line << " matches no written element";
      }
    }
  }
}

TEST(SmallMeshes, GmshPrismIsReorderedToTheVtkWedge) {
  // Gmsh's reference prism: triangle 0 1 2 at z = 0 counter-clockwise seen from
  // above, so its normal points into the prism, towards triangle 3 4 5.
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n"
      "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 0 1 1\n$EndNodes\n"
      "$Elements\n1\n1 6 2 0 1 1 2 3 4 5 6\n$EndElements\n";
  const MeshData mesh = read_mesh_file(write_temp("prism.msh", text));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ASSERT_EQ(mesh.elements[0].type, ElementType::Wedge);
  const std::uint32_t* v = mesh.vertices_of(mesh.elements[0]);
  auto p = [&](int k) { return mesh.points[v[k]]; };
  // VTK: the first triangle's normal points away from the second triangle.
  EXPECT_LT((p(1) - p(0)).cross(p(2) - p(0)).dot(p(3) - p(0)), 0);
  // Both triangles run the same way round (i + 3 lies above i).
  EXPECT_GT((p(4) - p(3)).cross(p(5) - p(3)).dot((p(1) - p(0)).cross(p(2) - p(0))), 0);
  // Lateral edges still join i and i + 3.
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ((p(k + 3) - p(k)), Vec3(0, 0, 1));
}

}  // namespace
}  // namespace rift::test
