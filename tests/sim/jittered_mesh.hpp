// Meshes whose elements all differ: every vertex of a generated mesh moved
// by a random offset (in the plane for a 2D map), the same for a given seed.
#pragma once

#include <random>

#include "rift/gmap/gmap.hpp"

namespace rift::test {

inline void jitter_vertices(GMap& map, unsigned seed, Real amplitude) {
  const int n = map.dimension();
  auto position = map.embedding<Vec3>("position");
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> jitter(-amplitude, amplitude);
  map.for_each_cell(Orbit::cell(0, n), [&](Dart v) {
    position[v] += Vec3(jitter(rng), jitter(rng), n == 3 ? jitter(rng) : 0.0);
  });
}

}  // namespace rift::test
