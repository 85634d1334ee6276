// Wavefront OBJ: only geometry and polygons matter to a G-map; texture
// coordinates, normals, groups, smoothing and materials are skipped.
#include <array>
#include <string_view>
#include <vector>

#include "rift/io/element_collector.hpp"
#include "rift/io/readers.hpp"
#include "rift/io/text_cursor.hpp"

namespace rift::io {

namespace {

// Statements that carry nothing a G-map uses. Free-form curves and surfaces
// are listed too: skipping them is better than refusing a file for them.
constexpr std::array<std::string_view, 27> kIgnored = {
    "vt",   "vn",   "vp",   "g",    "o",     "s",    "usemtl", "mtllib",   "cstype",
    "deg",  "bmat", "step", "curv", "curv2", "surf", "parm",   "trim",     "hole",
    "scrv", "sp",   "end",  "con",  "mg",    "lod",  "bevel",  "c_interp", "d_interp"};

bool is_ignored(std::string_view key) {
  for (std::string_view k : kIgnored) {
    if (k == key) return true;
  }
  return false;
}

}  // namespace

MeshData read_obj(const std::string& source, std::string_view text) {
  TextCursor in(source, text, 1, '#');
  MeshData mesh;
  mesh.source = source;
  ElementCollector elements;
  std::vector<std::uint32_t> face;
  std::vector<int> face_lines;
  std::vector<std::int64_t> face_indices;  // all faces' indices, flat
  std::vector<std::uint32_t> face_sizes;

  while (!in.at_end()) {
    const Token key = in.next();
    if (key.text == "v") {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        const Token t = in.next_on_line();
        if (t.empty()) {
          in.fail(key.line, "vertex " + std::to_string(mesh.points.size() + 1) + " has " +
                                std::to_string(c) + " coordinates, expected 3");
        }
        p[c] = in.to_coordinate(t, "a vertex coordinate");
      }
      mesh.points.push_back(p);
      in.skip_line();  // an optional w or a vertex colour
    } else if (key.text == "f") {
      std::uint32_t n = 0;
      for (Token t = in.next_on_line(); !t.empty(); t = in.next_on_line()) {
        // v, v/vt, v//vn or v/vt/vn: the vertex is what precedes the first '/'.
        const Token v{t.text.substr(0, t.text.find('/')), t.line};
        if (v.empty())
          in.fail(t.line, "face corner " + quote_text(t.text) + " has no vertex index");
        const std::int64_t index = in.to_integer(v, "a vertex index");
        if (index == 0) in.fail(t.line, "vertex index 0 is invalid (OBJ indices start at 1)");
        std::int64_t resolved = index - 1;
        if (index < 0) {
          // Relative to the vertices defined so far: -1 is the last one.
          resolved = static_cast<std::int64_t>(mesh.points.size()) + index;
          if (resolved < 0) {
            in.fail(t.line, "relative vertex index " + std::to_string(index) +
                                " reaches before the first vertex (" +
                                std::to_string(mesh.points.size()) + " defined so far)");
          }
        }
        face_indices.push_back(resolved);
        ++n;
      }
      if (n < 3) {
        in.fail(key.line, "face has " + std::to_string(n) + " vertices, at least 3 are needed");
      }
      face_sizes.push_back(n);
      face_lines.push_back(key.line);
    } else if (key.text == "l" || key.text == "p") {
      elements.ignore_lower_dimensional();
      in.skip_line();
    } else if (is_ignored(key.text)) {
      in.skip_line();
    } else {
      in.fail(key.line, "unknown OBJ statement " + quote_text(key.text));
    }
  }

  // Positive indices may refer to vertices defined later in the file, so the
  // range check waits until every vertex is known.
  std::size_t offset = 0;
  for (std::size_t f = 0; f < face_sizes.size(); ++f) {
    face.clear();
    for (std::uint32_t k = 0; k < face_sizes[f]; ++k) {
      const std::int64_t index = face_indices[offset + k];
      if (index >= static_cast<std::int64_t>(mesh.points.size())) {
        in.fail(face_lines[f], "face refers to vertex " + std::to_string(index + 1) +
                                   ", but the file defines " + std::to_string(mesh.points.size()) +
                                   " vertices");
      }
      face.push_back(static_cast<std::uint32_t>(index));
    }
    offset += face_sizes[f];
    elements.add(ElementType::Polygon, face, face_lines[f]);
  }
  elements.finish(mesh, 0);
  return mesh;
}

}  // namespace rift::io
