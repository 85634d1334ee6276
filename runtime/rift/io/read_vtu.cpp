// VTK XML unstructured grids (.vtu) with ASCII data arrays. The XML is parsed
// by pugixml; the text of each DataArray goes through the same TextCursor as
// the other formats, started at the array's line so messages name file lines.
#include <pugixml.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "rift/io/readers.hpp"
#include "rift/io/vtk_cells.hpp"

namespace rift::io {

namespace {

class VtuReader {
 public:
  VtuReader(const std::string& source, std::string_view text) : source_(source), text_(text) {
    mesh_.source = source;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') line_starts_.push_back(i + 1);
    }
  }

  MeshData read() {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed =
        doc.load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
      fail(line_at(parsed.offset), std::string("malformed XML: ") + parsed.description());
    }
    const pugi::xml_node root = doc.child("VTKFile");
    if (!root) fail(0, "not a VTK XML file: there is no VTKFile element");
    const std::string type = root.attribute("type").value();
    if (type != "UnstructuredGrid") {
      fail(line_of(root),
           "unsupported VTK XML dataset type '" + type + "' (rift reads UnstructuredGrid)");
    }
    const pugi::xml_node grid = root.child("UnstructuredGrid");
    if (!grid) fail(line_of(root), "the VTKFile has no UnstructuredGrid element");
    bool any = false;
    for (const pugi::xml_node piece : grid.children("Piece")) {
      read_piece(piece);
      any = true;
    }
    if (!any) fail(line_of(grid), "the UnstructuredGrid has no Piece");
    elements_.finish(mesh_, 0);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw MeshError(source_, line, problem);
  }

  int line_at(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;  // pugixml could not tell
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(),
                                     static_cast<std::size_t>(offset));
    // line_starts_ holds the offset where each line begins; the number of
    // line starts at or before `offset` is its 1-based line.
    return static_cast<int>(it - line_starts_.begin());
  }
  int line_of(const pugi::xml_node node) const { return line_at(node.offset_debug()); }

  std::size_t count_attribute(const pugi::xml_node node, const char* name) const {
    const pugi::xml_attribute a = node.attribute(name);
    const int line = line_of(node);
    if (!a) fail(line, std::string("<") + node.name() + "> has no " + name + " attribute");
    const TextCursor in(source_, {}, line);
    return in.to_count(Token{a.value(), line}, name);
  }

  // A cursor over the values of an ASCII DataArray.
  TextCursor values_of(const pugi::xml_node array, const std::string& what) const {
    const int line = line_of(array);
    if (!array) fail(line, "missing DataArray: " + what);
    const std::string format = array.attribute("format").value();
    if (format == "binary" || format == "appended") {
      fail(line, "DataArray " + what + " is in " + format +
                     " format, which rift does not read; save the file with ASCII data");
    }
    if (format != "ascii") fail(line, "DataArray " + what + " has unknown format '" + format + "'");
    const pugi::xml_node text = array.first_child();
    if (!text || (text.type() != pugi::node_pcdata && text.type() != pugi::node_cdata)) {
      return TextCursor(source_, {}, line);
    }
    return TextCursor(source_, text.value(), line_of(text));
  }

  Token value(TextCursor& in, const pugi::xml_node array, const std::string& what, std::size_t done,
              std::size_t announced) const {
    const Token t = in.next();
    if (t.empty()) {
      in.fail(t.line, "DataArray " + what + " (line " + std::to_string(line_of(array)) +
                          ") holds " + std::to_string(done) + " values, " +
                          std::to_string(announced) + " expected");
    }
    return t;
  }

  void no_more(TextCursor& in, const std::string& what, std::size_t announced) const {
    const Token extra = in.next();
    if (!extra.empty()) {
      in.fail(extra.line, "DataArray " + what + " holds more than the " +
                              std::to_string(announced) + " values expected");
    }
  }

  static pugi::xml_node named_array(const pugi::xml_node parent, const char* name) {
    return parent.find_child_by_attribute("DataArray", "Name", name);
  }

  void read_piece(const pugi::xml_node piece) {
    const std::size_t n_points = count_attribute(piece, "NumberOfPoints");
    const std::size_t n_cells = count_attribute(piece, "NumberOfCells");
    const std::size_t base = mesh_.points.size();

    const pugi::xml_node points = piece.child("Points");
    if (!points) fail(line_of(piece), "the Piece has no Points");
    const pugi::xml_node point_array = points.child("DataArray");
    const std::string components = point_array.attribute("NumberOfComponents").as_string("1");
    if (point_array && components != "3") {
      fail(line_of(point_array), "Points have " + components + " components, expected 3");
    }
    TextCursor coords = values_of(point_array, "Points");
    for (std::size_t k = 0; k < n_points; ++k) {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        const Token t =
            value(coords, point_array, "Points", 3 * k + static_cast<std::size_t>(c), 3 * n_points);
        p[c] = coords.to_real(
            t, "coordinate " + std::to_string(c + 1) + " of point " + std::to_string(k));
      }
      mesh_.points.push_back(p);
    }
    no_more(coords, "Points", 3 * n_points);

    const pugi::xml_node cells = piece.child("Cells");
    if (!cells) {
      if (n_cells == 0) return;
      fail(line_of(piece), "the Piece announces cells but has no Cells element");
    }
    const pugi::xml_node offsets_array = named_array(cells, "offsets");
    const pugi::xml_node conn_array = named_array(cells, "connectivity");
    const pugi::xml_node types_array = named_array(cells, "types");
    if (!offsets_array || !conn_array || !types_array) {
      fail(line_of(cells), "Cells needs DataArrays named connectivity, offsets and types");
    }

    // VTU offsets are end offsets: cell c ends at offsets[c].
    TextCursor offs = values_of(offsets_array, "offsets");
    std::vector<std::size_t> ends;
    ends.reserve(offs.reserve_limit(n_cells));
    for (std::size_t c = 0; c < n_cells; ++c) {
      const Token t = value(offs, offsets_array, "offsets", c, n_cells);
      const std::size_t end = offs.to_count(t, "an offset");
      if (end < (ends.empty() ? 0 : ends.back())) {
        offs.fail(t.line, "offset " + std::to_string(end) + " of cell " + std::to_string(c) +
                              " is smaller than the one before");
      }
      ends.push_back(end);
    }
    no_more(offs, "offsets", n_cells);

    TextCursor types = values_of(types_array, "types");
    std::vector<Token> type_tokens;
    for (std::size_t c = 0; c < n_cells; ++c)
      type_tokens.push_back(value(types, types_array, "types", c, n_cells));
    no_more(types, "types", n_cells);

    TextCursor conn = values_of(conn_array, "connectivity");
    const std::size_t total = ends.empty() ? 0 : ends.back();
    std::vector<std::uint32_t> ids;
    std::size_t read = 0;
    for (std::size_t c = 0; c < n_cells; ++c) {
      ids.clear();
      int line = 0;
      for (; read < ends[c]; ++read) {
        const Token t = value(conn, conn_array, "connectivity", read, total);
        if (line == 0) line = t.line;
        ids.push_back(static_cast<std::uint32_t>(base + vtk_point_id(conn, t, n_points, c)));
      }
      add_vtk_cell(types, elements_, type_tokens[c], ids, line ? line : type_tokens[c].line, c);
    }
    no_more(conn, "connectivity", total);
  }

  std::string source_;
  std::string_view text_;
  std::vector<std::size_t> line_starts_{0};
  MeshData mesh_;
  ElementCollector elements_;
};

}  // namespace

MeshData read_vtu(const std::string& source, std::string_view text) {
  return VtuReader(source, text).read();
}

}  // namespace rift::io
