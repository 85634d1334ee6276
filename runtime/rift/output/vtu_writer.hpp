// VTK XML unstructured grid (.vtu) files, one per frame, in ASCII with every
// real written exactly (shortest round-trip text), so ParaView and any XML
// parser read them.
#pragma once

#include <filesystem>
#include <string>

#include "rift/output/frame_mesh.hpp"

namespace rift {

/// Writes frames as .vtu files, reusing one text buffer across frames.
///
/// Contents: the points; the elements as VTK cells (polygons, or tetra, hexa,
/// wedge, pyramid, polyhedron); point data from FrameMesh::point_data
/// (velocity, force, point_index when present); cell data element_id, torn
/// and FrameMesh::cell_data; field data TimeValue.
class VtuWriter {
 public:
  /// Writes `frame` to `path` atomically. Throws OutputError.
  void write(const FrameMesh& frame, const std::filesystem::path& path, double time);
  /// The text of the last file written.
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

/// Builds the .vtu document of `frame` into `out` (cleared first).
void format_vtu(const FrameMesh& frame, double time, std::string& out);

}  // namespace rift
