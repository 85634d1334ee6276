// Mesh file readers. Each returns plain element lists (MeshData) or throws
// MeshError naming the file, the line and the problem.
#pragma once

#include <string>

#include "rift/mesh/mesh_data.hpp"
#include "rift/mesh/mesh_error.hpp"

namespace rift {

/// Reads a mesh file, choosing the reader from the extension:
/// .obj, .msh (Gmsh 1, 2.2 and 4.1 ASCII), .mesh (Medit), .vtu (ASCII), .vtk (legacy ASCII).
MeshData read_mesh_file(const std::string& path);

}  // namespace rift
