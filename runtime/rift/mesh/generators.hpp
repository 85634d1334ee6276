// Structured meshes: the 2D grids of the paper's cloth (quads, triangles and
// the "Mix" mesh) and 3D blocks of hexahedra or tetrahedra.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "rift/mesh/mesh_data.hpp"

namespace rift {

enum class GridKind { Quad, Tri, Mix };
enum class BlockKind { Hex, Tet };

/// nx by ny cells over [0,1]x[0,1] in the z = 0 plane. Tri splits every quad
/// along its (i,j)-(i+1,j+1) diagonal; Mix splits the quads with i + j even.
MeshData make_grid(GridKind kind, int nx, int ny);

/// nx by ny by nz cells over [0,1]^3. Tet splits each cube into the six
/// tetrahedra of its Kuhn subdivision (all around the main diagonal), which
/// is conforming across cubes.
MeshData make_block(BlockKind kind, int nx, int ny, int nz);

/// True when `spec` looks like a generator spelling rather than a file name.
bool is_generator_spec(std::string_view spec);

/// Builds the mesh named by a generator spelling: grid:quad:NxM,
/// grid:tri:NxM, grid:mix:NxM, block:hex:NxMxK, block:tet:NxMxK.
/// Throws std::invalid_argument explaining what is wrong with the spelling.
MeshData make_generated_mesh(std::string_view spec);

/// Checks a generator spelling without building its mesh (a scene names a
/// million-cell block cheaply). Throws like make_generated_mesh.
void check_generator_spec(std::string_view spec);

/// The generator spellings, for --help texts.
extern const char* const kGeneratorHelp;

}  // namespace rift
