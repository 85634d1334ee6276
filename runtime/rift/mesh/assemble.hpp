// Turns element lists into a G-map: each element becomes its darts (0-, 1- and,
// in 3D, 2-links inside it), then elements sharing an edge (2D) or a face (3D)
// are sewn. Embeddings created: `position` (vec3) and `point_index` (int, the
// index of the source point) on vertex orbits, and `element_index` (int, the
// index of the source element) on element orbits (<0,1> in 2D, <0,1,2> in 3D).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/mesh_data.hpp"

namespace rift {

/// An element named in a warning: its 0-based index in MeshData::elements and
/// its source line (0 for generated meshes). Meaningful when its count is not 0.
struct ElementExample {
  std::size_t index = 0;
  int line = 0;
  ElementType type = ElementType::Polygon;
};

/// What the assembler noticed and repaired or kept. The rules (docs/mesh-formats.md):
/// - a solid whose corners all have negative orientation is inverted: it is
///   reordered to positive orientation (tetrahedron: swap vertices 1 and 2;
///   hexahedron: swap the bottom and top quads; wedge: swap the two triangles;
///   pyramid: reverse the base) and counted;
/// - an element of (numerically) zero area or volume is kept as it is and
///   counted: it carries no mass and no stiffness, and the run warns;
/// - a solid with corners of both orientations is tangled: it is kept (reordered
///   if most of its volume is negative) and counted.
struct AssemblyReport {
  /// Edges (2D) or faces (3D) shared by more than two elements: the first two
  /// elements are sewn, the others keep that edge or face free.
  std::size_t nonmanifold_shared = 0;
  /// Solids given with negative orientation, reordered to positive.
  std::size_t reoriented_solids = 0;
  ElementExample first_reoriented;
  /// Polygons of zero area and solids of zero volume, kept as they are.
  std::size_t flat_elements = 0;
  ElementExample first_flat;
  /// Solids whose corners do not agree on an orientation (self-intersecting).
  std::size_t tangled_solids = 0;
  ElementExample first_tangled;
  /// Points that no element references; they do not appear in the map.
  std::size_t unused_points = 0;
};

/// The report's findings as warning sentences, without file name or prefix
/// ("2 inverted solids were reoriented (first: hexahedron 7, line 31)").
std::vector<std::string> assembly_warnings(const AssemblyReport& report, int dimension);

/// Vertex orbit of a map: <1,2> in 2D, <1,2,3> in 3D.
inline Orbit vertex_orbit(int dimension) {
  return Orbit::cell(0, dimension);
}

/// Builds the G-map of `mesh`. Throws MeshError naming `mesh.source` and the
/// element's source line for elements with a wrong vertex count, repeated
/// vertices, indices out of range or a dimension that does not match the mesh,
/// and for coordinates that are not finite or beyond kMaxCoordinate. Linear in
/// the total number of element vertices, whatever the size of one element.
GMap assemble_gmap(const MeshData& mesh, AssemblyReport* report = nullptr);

}  // namespace rift
