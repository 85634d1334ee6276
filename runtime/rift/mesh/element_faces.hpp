// The faces of each solid element type, as local vertex indices (VTK ordering).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "rift/mesh/mesh_data.hpp"

namespace rift {

struct LocalFace {
  std::uint8_t count;
  std::array<std::uint8_t, 4> v;
};

/// Faces of a solid element; empty for polygons.
std::span<const LocalFace> element_faces(ElementType type);
/// Number of vertices an element type must have (0: any >= 3, for polygons).
int element_vertex_count(ElementType type);
const char* element_name(ElementType type);

}  // namespace rift
