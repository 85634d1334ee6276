// VTK cell types, shared by the legacy .vtk and the XML .vtu readers: which
// types make a map, which are ignored, and the reorderings VTK needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "rift/io/element_collector.hpp"
#include "rift/io/text_cursor.hpp"

namespace rift::io {

/// A 0-based VTK point id, checked against the number of points. `cell` is
/// 0-based and only used in the message.
std::uint32_t vtk_point_id(const TextCursor& in, Token id, std::size_t points, std::size_t cell);
/// The same for an id already converted (binary data), found at `line`.
std::uint32_t vtk_point_id(const TextCursor& in, std::int64_t id, int line, std::size_t points,
                           std::size_t cell);

/// Adds cell `cell` (0-based) of VTK type `type` (read from `type_token`) with
/// the given point ids. Vertices, poly-vertices, lines and poly-lines are
/// ignored; triangle strips become triangles; pixels and voxels are reordered to
/// quads and hexahedra. Any other type, or a point count that does not fit the
/// type, is an error at `line` (the cell's line) or at the type's line.
void add_vtk_cell(const TextCursor& in, ElementCollector& out, Token type_token,
                  std::span<const std::uint32_t> ids, int line, std::size_t cell);
/// The same for a type code already converted (binary data), found at `type_line`;
/// `group`: the cell's physical group (an integer cell data array), if any.
void add_vtk_cell(const TextCursor& in, ElementCollector& out, std::int64_t code, int type_line,
                  std::span<const std::uint32_t> ids, int line, std::size_t cell,
                  std::optional<std::int64_t> group = std::nullopt);

}  // namespace rift::io
