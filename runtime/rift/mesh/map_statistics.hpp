// Cell counts of a G-map, as `rift info` reports them. Counts are orbits, so a
// non-manifold vertex (two separate fans) counts twice.
#pragma once

#include <cstddef>
#include <string>

#include "rift/gmap/gmap.hpp"

namespace rift {

struct MapStatistics {
  int dimension = 0;
  std::size_t darts = 0;
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t volumes = 0;  ///< 0 for a 2D map
  std::size_t components = 0;
  /// Boundary edges (2D: edges with a 2-free dart) or faces (3D: 3-free).
  std::size_t boundary = 0;

  /// "boundary_edges" in 2D, "boundary_faces" in 3D.
  const char* boundary_key() const { return dimension == 3 ? "boundary_faces" : "boundary_edges"; }
  /// One line: dimension=2 darts=... boundary_edges=...
  std::string to_line() const;
  /// One JSON object with the same keys.
  std::string to_json() const;
};

MapStatistics compute_statistics(const GMap& map);

}  // namespace rift
