// VTK XML unstructured grids (.vtu). The XML is parsed by pugixml. A data array
// is ASCII text, inline base64 (format="binary") or a slice of the appended
// data (format="appended", raw bytes or base64), optionally zlib-compressed
// (vtk_binary.hpp decodes those). ASCII arrays go through the same TextCursor
// as the other formats, started at the array's line, so messages name file
// lines; binary arrays are reported at their DataArray's line.
//
// Raw appended data is not XML (any byte may occur in it), so the document is
// cut at <AppendedData> and only the part before it goes to the XML parser.
#include <pugixml.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "rift/io/readers.hpp"
#include "rift/io/vtk_binary.hpp"
#include "rift/io/vtk_cells.hpp"

namespace rift::io {

namespace {

struct ScalarType {
  const char* name;
  int bytes;
  bool real;
  bool is_signed;
};

constexpr ScalarType kScalarTypes[] = {{"Int8", 1, false, true},   {"UInt8", 1, false, false},
                                       {"Int16", 2, false, true},  {"UInt16", 2, false, false},
                                       {"Int32", 4, false, true},  {"UInt32", 4, false, false},
                                       {"Int64", 8, false, true},  {"UInt64", 8, false, false},
                                       {"Float32", 4, true, true}, {"Float64", 8, true, true}};

const ScalarType* scalar_type(std::string_view name) {
  for (const ScalarType& t : kScalarTypes) {
    if (name == t.name) return &t;
  }
  return nullptr;
}

// The values of one DataArray, ASCII or binary, handed out in order.
class ArrayValues {
 public:
  ArrayValues(TextCursor ascii, std::string what, int line)
      : text_(std::move(ascii)), what_(std::move(what)), line_(line) {}
  ArrayValues(TextCursor messages, std::string what, int line, std::vector<std::uint8_t> bytes,
              const ScalarType& type, bool big_endian)
      : text_(std::move(messages)),
        what_(std::move(what)),
        line_(line),
        binary_(true),
        bytes_(std::move(bytes)),
        type_(&type),
        big_endian_(big_endian) {
    if (bytes_.size() % static_cast<std::size_t>(type.bytes) != 0) {
      text_.fail(line_, "DataArray " + what_ + " holds " + std::to_string(bytes_.size()) +
                            " bytes, not a whole number of " + type.name + " values");
    }
  }

  const TextCursor& cursor() const { return text_; }
  /// Line of the last value handed out (the array's line for binary data).
  int last_line() const { return last_line_; }

  double coordinate(std::size_t done, std::size_t announced, const std::string& what) {
    if (!binary_) return text_.to_coordinate(token(done, announced), what);
    const double v = binary_value(done, announced).real;
    if (!std::isfinite(v)) text_.fail(line_, what + " is not a finite number");
    if (std::abs(v) > kMaxCoordinate) {
      text_.fail(line_, what + " (" + std::to_string(v) +
                            ") is beyond +-1e30, the largest coordinate rift accepts; rescale "
                            "the mesh");
    }
    return v;
  }

  std::int64_t integer(std::size_t done, std::size_t announced, const char* what) {
    if (!binary_) return text_.to_integer(token(done, announced), what);
    if (type_->real) {
      text_.fail(line_,
                 "DataArray " + what_ + " has type " + type_->name + ", expected an integer type");
    }
    const Value v = binary_value(done, announced);
    if (v.too_large) {
      text_.fail(line_, std::string(what) + " in DataArray " + what_ + " is out of range");
    }
    return v.integer;
  }

  void no_more(std::size_t announced) {
    const bool extra =
        binary_ ? next_ * static_cast<std::size_t>(type_->bytes) < bytes_.size() : !text_.at_end();
    if (extra) {
      text_.fail(binary_ ? line_ : text_.peek().line,
                 "DataArray " + what_ + " holds more than the " + std::to_string(announced) +
                     " values expected");
    }
  }

 private:
  struct Value {
    double real = 0;
    std::int64_t integer = 0;
    bool too_large = false;
  };

  [[noreturn]] void short_of(int line, std::size_t done, std::size_t announced) const {
    text_.fail(line, "DataArray " + what_ + " (line " + std::to_string(line_) + ") holds " +
                         std::to_string(done) + " values, " + std::to_string(announced) +
                         " expected");
  }

  Token token(std::size_t done, std::size_t announced) {
    const Token t = text_.next();
    if (t.empty()) short_of(t.line, done, announced);
    last_line_ = t.line;
    return t;
  }

  Value binary_value(std::size_t done, std::size_t announced) {
    const auto size = static_cast<std::size_t>(type_->bytes);
    if ((next_ + 1) * size > bytes_.size()) short_of(line_, done, announced);
    std::uint64_t raw = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const std::size_t byte = big_endian_ ? k : size - 1 - k;
      raw = (raw << 8) | bytes_[next_ * size + byte];
    }
    ++next_;
    last_line_ = line_;
    Value v;
    if (type_->real) {
      v.real = size == 4
                   ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(raw)))
                   : std::bit_cast<double>(raw);
      return v;
    }
    const int bits = 8 * type_->bytes;
    if (type_->is_signed && bits < 64 && (raw >> (bits - 1)) != 0) {
      raw |= ~std::uint64_t{0} << bits;  // sign extension
    }
    if (!type_->is_signed && raw > static_cast<std::uint64_t>(INT64_MAX)) v.too_large = true;
    v.integer = static_cast<std::int64_t>(raw);
    v.real = static_cast<double>(v.integer);
    return v;
  }

  TextCursor text_;
  std::string what_;
  int line_;
  int last_line_ = 0;
  bool binary_ = false;
  std::vector<std::uint8_t> bytes_;
  const ScalarType* type_ = nullptr;
  bool big_endian_ = false;
  std::size_t next_ = 0;
};

class VtuReader {
 public:
  VtuReader(const std::string& source, std::string_view text) : source_(source), text_(text) {
    mesh_.source = source;
  }

  MeshData read() {
    std::string xml = split_appended_data();
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed =
        doc.load_buffer_inplace(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8);
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
    read_encoding(root);
    const pugi::xml_node grid = root.child("UnstructuredGrid");
    if (!grid) fail(line_of(root), "the VTKFile has no UnstructuredGrid element");
    bool any = false;
    for (const pugi::xml_node piece : grid.children("Piece")) {
      read_piece(piece);
      any = true;
    }
    if (!any) fail(line_of(grid), "the UnstructuredGrid has no Piece");
    elements_.finish(mesh_, 0);
    // Point groups count only if every piece gave them.
    if (points_without_group_) mesh_.point_tags.clear();
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw MeshError(source_, line, problem);
  }

  // Returns the XML part of the file and records where the appended data is.
  std::string split_appended_data() {
    const std::size_t tag = text_.find("<AppendedData");
    if (tag == std::string_view::npos) return std::string(text_);
    const int line = line_at(static_cast<std::ptrdiff_t>(tag));
    const std::size_t tag_end = text_.find('>', tag);
    if (tag_end == std::string_view::npos) fail(line, "the <AppendedData> tag is not closed");
    const std::string_view tag_text = text_.substr(tag, tag_end - tag);
    if (tag_text.find("encoding=\"raw\"") != std::string_view::npos) {
      appended_base64_ = false;
    } else if (tag_text.find("encoding=\"base64\"") != std::string_view::npos) {
      appended_base64_ = true;
    } else {
      fail(line, "<AppendedData> needs encoding=\"raw\" or encoding=\"base64\"");
    }
    std::size_t mark = tag_end + 1;
    while (mark < text_.size() && (text_[mark] == ' ' || text_[mark] == '\n' ||
                                   text_[mark] == '\r' || text_[mark] == '\t'))
      ++mark;
    if (mark >= text_.size() || text_[mark] != '_') {
      fail(line, "the appended data must start with '_' after <AppendedData>");
    }
    appended_ = text_.substr(mark + 1);
    has_appended_ = true;
    return std::string(text_.substr(0, tag)) + "</VTKFile>";
  }

  void read_encoding(const pugi::xml_node root) {
    const std::string header = root.attribute("header_type").as_string("UInt32");
    if (header == "UInt32") {
      layout_.header_bytes = 4;
    } else if (header == "UInt64") {
      layout_.header_bytes = 8;
    } else {
      fail(line_of(root), "unknown header_type '" + header + "' (UInt32 or UInt64)");
    }
    const std::string order = root.attribute("byte_order").as_string("LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") {
      fail(line_of(root), "unknown byte_order '" + order + "' (LittleEndian or BigEndian)");
    }
    layout_.big_endian = order == "BigEndian";
    const std::string compressor = root.attribute("compressor").value();
    if (compressor == "vtkZLibDataCompressor") {
      layout_.compressed = true;
    } else if (!compressor.empty()) {
      fail(line_of(root), "compressor '" + compressor +
                              "' is not supported (rift reads vtkZLibDataCompressor or none)");
    }
  }

  // Lines are counted on demand from the last answer: the arrays are visited
  // in file order, so the counting is linear overall, and a file of a hundred
  // million line ends needs no table of them.
  int line_at(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;  // pugixml could not tell
    const auto at = std::min(static_cast<std::size_t>(offset), text_.size());
    if (at < counted_to_) {
      counted_to_ = 0;
      counted_line_ = 1;
    }
    counted_line_ +=
        static_cast<int>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(counted_to_),
                                    text_.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    counted_to_ = at;
    return counted_line_;
  }
  int line_of(const pugi::xml_node node) const { return line_at(node.offset_debug()); }

  std::size_t count_attribute(const pugi::xml_node node, const char* name) const {
    const pugi::xml_attribute a = node.attribute(name);
    const int line = line_of(node);
    if (!a) fail(line, std::string("<") + node.name() + "> has no " + name + " attribute");
    const TextCursor in(source_, {}, line);
    return in.to_count(Token{a.value(), line}, name);
  }

  ArrayValues values_of(const pugi::xml_node array, const std::string& what) const {
    const int line = line_of(array);
    if (!array) fail(line, "missing DataArray: " + what);
    const std::string format = array.attribute("format").value();
    if (format == "ascii") {
      const pugi::xml_node text = array.first_child();
      if (!text || (text.type() != pugi::node_pcdata && text.type() != pugi::node_cdata)) {
        return ArrayValues(TextCursor(source_, {}, line), what, line);
      }
      return ArrayValues(TextCursor(source_, text.value(), line_of(text)), what, line);
    }
    const std::string type_name = array.attribute("type").value();
    const ScalarType* type = scalar_type(type_name);
    if (!type) {
      fail(line, "DataArray " + what + " has unknown type '" + type_name +
                     "' (Int8 to UInt64, Float32 or Float64)");
    }
    VtkBinaryLayout layout = layout_;
    std::string_view data;
    if (format == "binary") {
      layout.base64 = true;
      const pugi::xml_node text = array.first_child();
      if (text && (text.type() == pugi::node_pcdata || text.type() == pugi::node_cdata)) {
        data = text.value();
      }
    } else if (format == "appended") {
      if (!has_appended_) {
        fail(line,
             "DataArray " + what + " is in appended format, but the file has no <AppendedData>");
      }
      layout.base64 = appended_base64_;
      const pugi::xml_attribute offset_attribute = array.attribute("offset");
      if (!offset_attribute) fail(line, "DataArray " + what + " is appended but has no offset");
      const TextCursor in(source_, {}, line);
      const std::int64_t offset =
          in.to_integer(Token{offset_attribute.value(), line}, "the offset");
      if (offset < 0 || static_cast<std::uint64_t>(offset) >= appended_.size()) {
        fail(line, "DataArray " + what + " has offset " + std::to_string(offset) +
                       ", outside the appended data (" + std::to_string(appended_.size()) +
                       " bytes)");
      }
      data = appended_.substr(static_cast<std::size_t>(offset));
    } else {
      fail(line, "DataArray " + what + " has unknown format '" + format +
                     "' (ascii, binary or appended)");
    }
    std::vector<std::uint8_t> bytes;
    try {
      bytes = decode_vtk_array(data, layout);
    } catch (const VtkDataError& e) {
      fail(line, "DataArray " + what + " (" + format + (layout.compressed ? ", zlib" : "") +
                     "): " + e.what());
    }
    return ArrayValues(TextCursor(source_, {}, line), what, line, std::move(bytes), *type,
                       layout.big_endian);
  }

  static pugi::xml_node named_array(const pugi::xml_node parent, const char* name) {
    return parent.find_child_by_attribute("DataArray", "Name", name);
  }

  // The array of a CellData or PointData that holds physical groups: the one
  // its Scalars attribute names if that is an integer array of one component,
  // else the first such array (meshio writes gmsh:physical first).
  static pugi::xml_node group_array(const pugi::xml_node data) {
    if (!data) return {};
    auto holds_groups = [](const pugi::xml_node a) {
      const ScalarType* t = scalar_type(a.attribute("type").value());
      return t && !t->real && a.attribute("NumberOfComponents").as_int(1) == 1;
    };
    if (const std::string scalars = data.attribute("Scalars").value(); !scalars.empty()) {
      const pugi::xml_node a = named_array(data, scalars.c_str());
      if (a && holds_groups(a)) return a;
    }
    for (pugi::xml_node a = data.child("DataArray"); a; a = a.next_sibling("DataArray"))
      if (holds_groups(a)) return a;
    return {};
  }

  // The values of the group array of `data` (CellData or PointData), one per
  // entity; empty if it has none.
  std::vector<std::int64_t> groups_of(const pugi::xml_node data, std::size_t count) const {
    std::vector<std::int64_t> groups;
    const pugi::xml_node array = group_array(data);
    if (!array) return groups;
    ArrayValues values =
        values_of(array, std::string(data.name()) + " '" + array.attribute("Name").value() + "'");
    for (std::size_t k = 0; k < count; ++k) {
      grow_for_next_entry(groups, count);
      groups.push_back(values.integer(k, count, "a group"));
    }
    values.no_more(count);
    return groups;
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
    ArrayValues coords = values_of(point_array, "Points");
    for (std::size_t k = 0; k < n_points; ++k) {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        p[c] = coords.coordinate(
            3 * k + static_cast<std::size_t>(c), 3 * n_points,
            "coordinate " + std::to_string(c + 1) + " of point " + std::to_string(k));
      }
      mesh_.points.push_back(p);
    }
    coords.no_more(3 * n_points);
    const std::vector<std::int64_t> point_groups = groups_of(piece.child("PointData"), n_points);
    if (point_groups.empty()) points_without_group_ = true;
    mesh_.point_tags.resize(base);
    mesh_.point_tags.insert(mesh_.point_tags.end(), point_groups.begin(), point_groups.end());
    mesh_.point_tags.resize(base + n_points, 0);

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
    ArrayValues offs = values_of(offsets_array, "offsets");
    std::vector<std::size_t> ends;
    for (std::size_t c = 0; c < n_cells; ++c) {
      const std::int64_t end = offs.integer(c, n_cells, "an offset");
      if (end < 0 || static_cast<std::size_t>(end) < (ends.empty() ? 0 : ends.back())) {
        offs.cursor().fail(offs.last_line(), "offset " + std::to_string(end) + " of cell " +
                                                 std::to_string(c) +
                                                 " is smaller than the one before");
      }
      grow_for_next_entry(ends, n_cells);
      ends.push_back(static_cast<std::size_t>(end));
    }
    offs.no_more(n_cells);

    ArrayValues types = values_of(types_array, "types");
    std::vector<std::pair<std::int64_t, int>> type_codes;  // code, line
    type_codes.reserve(ends.size());
    for (std::size_t c = 0; c < n_cells; ++c) {
      const std::int64_t code = types.integer(c, n_cells, "a cell type");
      type_codes.emplace_back(code, types.last_line());
    }
    types.no_more(n_cells);

    const std::vector<std::int64_t> cell_groups = groups_of(piece.child("CellData"), n_cells);

    ArrayValues conn = values_of(conn_array, "connectivity");
    const std::size_t total = ends.empty() ? 0 : ends.back();
    std::vector<std::uint32_t> ids;
    std::size_t read = 0;
    for (std::size_t c = 0; c < n_cells; ++c) {
      ids.clear();
      int line = 0;
      for (; read < ends[c]; ++read) {
        const std::int64_t id = conn.integer(read, total, "a point id");
        if (line == 0) line = conn.last_line();
        ids.push_back(static_cast<std::uint32_t>(
            base + vtk_point_id(conn.cursor(), id, conn.last_line(), n_points, c)));
      }
      const auto [code, type_line] = type_codes[c];
      add_vtk_cell(types.cursor(), elements_, code, type_line, ids, line ? line : type_line, c,
                   cell_groups.empty() ? std::nullopt : std::optional(cell_groups[c]));
    }
    conn.no_more(total);
  }

  std::string source_;
  std::string_view text_;
  std::string_view appended_;
  bool has_appended_ = false;
  bool appended_base64_ = false;
  VtkBinaryLayout layout_;
  mutable std::size_t counted_to_ = 0;
  mutable int counted_line_ = 1;
  MeshData mesh_;
  ElementCollector elements_;
  bool points_without_group_ = false;
};

}  // namespace

MeshData read_vtu(const std::string& source, std::string_view text) {
  return VtuReader(source, text).read();
}

}  // namespace rift::io
