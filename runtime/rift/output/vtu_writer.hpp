// VTK XML unstructured grid (.vtu) files, one per frame. By default the arrays
// are appended raw binary (little-endian, UInt64 headers, uncompressed), the
// layout ParaView writes itself: exact, smaller than text and without number
// formatting. ASCII (every real in its shortest exact text) is an option for
// diffable files and hand inspection.
#pragma once

#include <filesystem>
#include <string>

#include "rift/output/frame_mesh.hpp"

namespace rift {

enum class VtuEncoding {
  kAppendedBinary,  ///< <AppendedData encoding="raw">: compact and exact
  kAscii,           ///< values as text inside each DataArray
};

/// Writes frames as .vtu files, reusing one text buffer across frames.
///
/// Contents: the points; the elements as VTK cells (polygons, or tetra, hexa,
/// wedge, pyramid, polyhedron); point data from FrameMesh::point_data
/// (velocity, force, point_index when present); cell data element_id, torn
/// and FrameMesh::cell_data; field data TimeValue.
class VtuWriter {
 public:
  explicit VtuWriter(VtuEncoding encoding = VtuEncoding::kAppendedBinary) : encoding_(encoding) {}

  /// Writes `frame` to `path` atomically. Throws OutputError.
  void write(const FrameMesh& frame, const std::filesystem::path& path, double time);
  /// The bytes of the last file written.
  const std::string& text() const { return text_; }

 private:
  VtuEncoding encoding_;
  std::string text_;
  std::string appended_;
};

/// Builds the .vtu document of `frame` into `out` (cleared first). `scratch`
/// holds the appended data while the XML part is built (reused across frames).
void format_vtu(const FrameMesh& frame, double time, std::string& out,
                VtuEncoding encoding = VtuEncoding::kAppendedBinary,
                std::string* scratch = nullptr);

}  // namespace rift
