// Props drawn beside the body (obstacles): a triangle surface held as a
// FrameMesh, so that the renderer and the VTU writer take it as they take a
// frame of the body.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "rift/output/frame_mesh.hpp"

namespace rift {

/// Fills `out` with the triangles (indices into `points`) as faces and cells.
void make_scenery(std::span<const Vec3> points,
                  std::span<const std::array<std::uint32_t, 3>> triangles, FrameMesh& out);

}  // namespace rift
