// The paper's cloth (Fig. 14, Table 2) as docs/physics.md fixes it: a 1 m x
// 1 m grid of 10 x 10 patches hung vertically in the x-z plane, its two upper
// corners pinned, 100 g, 60 / 43 / 10 N/m, damping 0.1 N s/m, gravity 9.81,
// RK4 with dt = 5e-4 s.
#pragma once

#include <random>

#include "reference_cloth.hpp"
#include "rift/mesh/generators.hpp"

namespace rift::reference {

/// The time step of docs/physics.md ("Time step").
inline constexpr Real kPaperDt = 5e-4;

inline MeshData hanging_grid(GridKind kind, int nx, int ny) {
  MeshData mesh = make_grid(kind, nx, ny);
  hang_vertically(mesh);
  return mesh;
}

/// The hanging cloth with its two upper corners, (0, ny) and (nx, ny), pinned.
inline ReferenceCloth paper_cloth(GridKind kind = GridKind::Quad, int nx = 10, int ny = 10,
                                  const ClothParameters& params = {}) {
  ReferenceCloth cloth(hanging_grid(kind, nx, ny), params);
  cloth.pin(grid_point(nx, 0, ny));
  cloth.pin(grid_point(nx, nx, ny));
  return cloth;
}

/// Moves every free vertex by a uniform random offset in [-amplitude, amplitude]^3.
inline void jiggle(ReferenceCloth& cloth, Real amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> offset(-amplitude, amplitude);
  for (std::uint32_t i = 0; i < cloth.vertex_count(); ++i) {
    const Vec3 d(offset(rng), offset(rng), offset(rng));
    if (!cloth.pinned(i)) cloth.positions()[i] += d;
  }
}

}  // namespace rift::reference
