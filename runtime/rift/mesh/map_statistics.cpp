#include "rift/mesh/map_statistics.hpp"

#include <fmt/format.h>

namespace rift {

MapStatistics compute_statistics(const GMap& map) {
  MapStatistics s;
  const int n = map.dimension();
  s.dimension = n;
  s.darts = map.size();
  s.vertices = map.count_cells_of_dimension(0);
  s.edges = map.count_cells_of_dimension(1);
  s.faces = n >= 2 ? map.count_cells_of_dimension(2) : 0;
  s.volumes = n >= 3 ? map.count_cells_of_dimension(3) : 0;
  s.components = map.count_cells(Orbit::all(n));
  // A boundary (n-1)-cell is n-free on all its darts, so testing the dart
  // that represents the cell is enough.
  map.for_each_cell(Orbit::cell(n - 1, n), [&](Dart d) {
    if (map.is_free(d, n)) ++s.boundary;
  });
  return s;
}

std::string MapStatistics::to_line() const {
  return fmt::format(
      "dimension={} darts={} vertices={} edges={} faces={} volumes={} components={} {}={}",
      dimension, darts, vertices, edges, faces, volumes, components, boundary_key(), boundary);
}

std::string MapStatistics::to_json() const {
  return fmt::format(
      "{{\"dimension\": {}, \"darts\": {}, \"vertices\": {}, \"edges\": {}, \"faces\": {}, "
      "\"volumes\": {}, \"components\": {}, \"{}\": {}}}",
      dimension, darts, vertices, edges, faces, volumes, components, boundary_key(), boundary);
}

}  // namespace rift
