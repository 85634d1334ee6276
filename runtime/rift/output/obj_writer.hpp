// Wavefront OBJ of a frame's boundary surface: one `v` per point (vertex
// orbit, so torn pieces have their own vertices) and one `f` per boundary
// face (2D: every face; 3D: faces with a 3-free dart). Faces made torn are
// in group `torn`, the others in group `intact`.
#pragma once

#include <filesystem>
#include <string>

#include "rift/output/frame_mesh.hpp"

namespace rift {

class ObjWriter {
 public:
  /// Writes `frame` to `path` atomically. Throws OutputError.
  void write(const FrameMesh& frame, const std::filesystem::path& path);
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

/// Builds the OBJ text of `frame` into `out` (cleared first).
void format_obj(const FrameMesh& frame, std::string& out);

}  // namespace rift
