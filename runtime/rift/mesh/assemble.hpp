// Turns element lists into a G-map: each element becomes its darts (0-, 1- and,
// in 3D, 2-links inside it), then elements sharing an edge (2D) or a face (3D)
// are sewn. Embeddings created: `position` (vec3) and `point_index` (int, the
// index of the source point) on vertex orbits, and `element_index` (int, the
// index of the source element) on element orbits (<0,1> in 2D, <0,1,2> in 3D).
#pragma once

#include <cstddef>

#include "rift/gmap/gmap.hpp"
#include "rift/mesh/mesh_data.hpp"

namespace rift {

struct AssemblyReport {
  /// Edges (2D) or faces (3D) shared by more than two elements: the first two
  /// elements are sewn, the others keep that edge or face free.
  std::size_t nonmanifold_shared = 0;
  /// Tetrahedra given with negative orientation, reordered to positive.
  std::size_t reoriented_tetrahedra = 0;
  /// Tetrahedra of (numerically) zero volume, kept as they are.
  std::size_t flat_tetrahedra = 0;
  /// Points that no element references; they do not appear in the map.
  std::size_t unused_points = 0;
};

/// Vertex orbit of a map: <1,2> in 2D, <1,2,3> in 3D.
inline Orbit vertex_orbit(int dimension) {
  return Orbit::cell(0, dimension);
}

/// Builds the G-map of `mesh`. Throws MeshError naming `mesh.source` and the
/// element's source line for elements with a wrong vertex count, repeated
/// vertices, indices out of range or a dimension that does not match the mesh.
GMap assemble_gmap(const MeshData& mesh, AssemblyReport* report = nullptr);

}  // namespace rift
