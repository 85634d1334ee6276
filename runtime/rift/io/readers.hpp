// One reader per format, on text already in memory. `source` is the name used
// in messages (the path). read_mesh_file() picks one from the extension; the
// readers are public so that tests and tools can parse text without a file.
#pragma once

#include <string>
#include <string_view>

#include "rift/mesh/mesh_data.hpp"
#include "rift/mesh/mesh_error.hpp"

namespace rift::io {

/// Wavefront OBJ: `v` and `f` (v, v/vt, v//vn, v/vt/vn, negative indices); a 2D map.
MeshData read_obj(const std::string& source, std::string_view text);
/// Gmsh .msh, legacy v1 ($NOD/$ELM), v2.2 and v4.1 ASCII.
MeshData read_gmsh(const std::string& source, std::string_view text);
/// Medit .mesh (ASCII), MeshVersionFormatted 1 or 2.
MeshData read_medit(const std::string& source, std::string_view text);
/// Legacy VTK .vtk (ASCII): UNSTRUCTURED_GRID and POLYDATA.
MeshData read_vtk_legacy(const std::string& source, std::string_view text);
/// VTK XML .vtu (ASCII data arrays): UnstructuredGrid.
MeshData read_vtu(const std::string& source, std::string_view text);

}  // namespace rift::io
