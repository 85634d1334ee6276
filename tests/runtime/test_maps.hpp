// Small maps built dart by dart for G-map tests.
#pragma once

#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift::test {

/// A polygon face of k edges (2k darts) in a map of the given dimension:
/// dart 2i lies at vertex i on edge i, dart 2i+1 at vertex i+1 on edge i.
inline Dart make_polygon(GMap& map, int k) {
  const Dart first = map.create_darts(2 * k);
  for (int i = 0; i < k; ++i) {
    map.link(first + 2 * i, first + 2 * i + 1, 0);
    map.link(first + 2 * i + 1, first + 2 * ((i + 1) % k), 1);
  }
  return first;
}

}  // namespace rift::test
