// A mesh as plain element lists: what importers and generators produce and
// the G-map assembler consumes. Vertex indices are 0-based.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rift/core/types.hpp"

namespace rift {

/// The largest coordinate magnitude a mesh may have. Areas, volumes, masses and
/// stiffnesses are products of two or three lengths (and material constants):
/// with |x| <= 1e30 they stay far below the double limit (1.8e308), whereas a
/// coordinate of 1e300 squares to infinity and turns masses into NaN. No
/// physical mesh comes near 1e30 in any length unit. Readers refuse larger
/// coordinates at their line; the assembler checks again after placement.
inline constexpr double kMaxCoordinate = 1e30;

enum class ElementType : std::uint8_t {
  Polygon,  ///< 2D: any polygon with >= 3 vertices (triangles and quads included)
  Tetra,    ///< 3D: 4 vertices, VTK ordering
  Hexa,     ///< 3D: 8 vertices, VTK ordering (bottom 0-3, top 4-7)
  Wedge,    ///< 3D: 6 vertices, VTK ordering (triangle 0-2, triangle 3-5)
  Pyramid,  ///< 3D: 5 vertices, VTK ordering (quad 0-3, apex 4)
};

/// Topological dimension of an element type: 2 for polygons, 3 for solids.
constexpr int element_dimension(ElementType t) {
  return t == ElementType::Polygon ? 2 : 3;
}

struct MeshElement {
  ElementType type;
  std::uint32_t first;  ///< offset of its first vertex in MeshData::element_vertices
  std::uint32_t count;  ///< number of vertices
  int source_line;      ///< line in the source file (0 for generated meshes)
};

struct MeshData {
  int dimension = 2;  ///< 2: a surface of polygons, 3: a volume of solids
  std::vector<Vec3> points;
  std::vector<std::uint32_t> element_vertices;
  std::vector<MeshElement> elements;
  std::string source;  ///< file name or generator spelling, for messages
  /// Physical group of each element (Gmsh physical tag, Medit reference),
  /// parallel to `elements`; empty when the file gives none.
  std::vector<std::int64_t> element_tags;
  /// Physical group of each point (VTU point data), parallel to `points`;
  /// empty when the file gives none.
  std::vector<std::int64_t> point_tags;

  void add_element(ElementType type, std::initializer_list<std::uint32_t> vertices,
                   int source_line = 0) {
    elements.push_back({type, static_cast<std::uint32_t>(element_vertices.size()),
                        static_cast<std::uint32_t>(vertices.size()), source_line});
    element_vertices.insert(element_vertices.end(), vertices.begin(), vertices.end());
  }
  template <class It>
  void add_element(ElementType type, It begin, It end, int source_line = 0) {
    const auto first = static_cast<std::uint32_t>(element_vertices.size());
    element_vertices.insert(element_vertices.end(), begin, end);
    elements.push_back(
        {type, first, static_cast<std::uint32_t>(element_vertices.size() - first), source_line});
  }
  const std::uint32_t* vertices_of(const MeshElement& e) const {
    return element_vertices.data() + e.first;
  }
};

}  // namespace rift
