// Legacy VTK (.vtk), ASCII. Header: a version line, a title line, ASCII or
// BINARY, then DATASET. UNSTRUCTURED_GRID gives POINTS, CELLS and CELL_TYPES;
// POLYDATA gives POINTS and POLYGONS (and strips, lines, vertices). Both the
// classic cell layout ("n id0 id1 ..." per cell) and the one of file version
// 5 (OFFSETS and CONNECTIVITY arrays) are read. Attribute data (POINT_DATA,
// CELL_DATA, FIELD) follows the geometry and is not needed, so reading stops there.
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "rift/io/readers.hpp"
#include "rift/io/vtk_cells.hpp"

namespace rift::io {

namespace {

bool same_word(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) ==
                  std::toupper(static_cast<unsigned char>(y));
         });
}

// Cells as flat lists: ids of cell c are connectivity[offsets[c] .. offsets[c+1]).
struct CellLists {
  std::vector<std::uint32_t> connectivity;
  std::vector<std::size_t> offsets{0};
  std::vector<int> lines;  // line of each cell's first value
  int header_line = 0;
  std::size_t size() const { return lines.size(); }
};

class VtkLegacyReader {
 public:
  VtkLegacyReader(const std::string& source, std::string_view text) : in_(source, text) {
    mesh_.source = source;
  }

  MeshData read() {
    read_header();
    bool grid = false;
    const Token dataset = in_.expect("DATASET");
    if (!same_word(dataset.text, "DATASET")) {
      in_.fail(dataset.line, "expected DATASET, found " + quote_text(dataset.text));
    }
    const Token kind = in_.expect("the dataset type");
    if (same_word(kind.text, "UNSTRUCTURED_GRID")) {
      grid = true;
    } else if (!same_word(kind.text, "POLYDATA")) {
      in_.fail(kind.line, "unsupported VTK dataset type " + quote_text(kind.text) +
                              " (rift reads UNSTRUCTURED_GRID and POLYDATA)");
    }
    CellLists cells;
    bool have_types = false;
    std::vector<Token> types;
    for (Token key = in_.next(); !key.empty(); key = in_.next()) {
      if (same_word(key.text, "POINTS")) {
        read_points(key);
      } else if (grid && same_word(key.text, "CELLS")) {
        cells = read_cells(key);
      } else if (grid && same_word(key.text, "CELL_TYPES")) {
        types = read_types(key, cells);
        have_types = true;
      } else if (!grid &&
                 (same_word(key.text, "POLYGONS") || same_word(key.text, "TRIANGLE_STRIPS") ||
                  same_word(key.text, "LINES") || same_word(key.text, "VERTICES"))) {
        add_poly_cells(key, read_cells(key));
      } else if (same_word(key.text, "METADATA")) {
        skip_metadata();
      } else if (same_word(key.text, "POINT_DATA") || same_word(key.text, "CELL_DATA") ||
                 same_word(key.text, "FIELD")) {
        break;
      } else {
        in_.fail(key.line, "unexpected keyword " + quote_text(key.text) + " in a VTK " +
                               std::string(grid ? "UNSTRUCTURED_GRID" : "POLYDATA"));
      }
    }
    if (grid) {
      if (cells.header_line == 0) in_.fail(0, "the file has no CELLS section");
      if (!have_types) in_.fail(0, "the file has no CELL_TYPES section");
      for (std::size_t c = 0; c < cells.size(); ++c) {
        add_vtk_cell(in_, elements_, types[c], cell_ids(cells, c), cells.lines[c], c);
      }
    }
    elements_.finish(mesh_, 0);
    return std::move(mesh_);
  }

 private:
  void read_header() {
    const Token version_line = in_.take_line();
    const std::string_view prefix = "# vtk DataFile Version ";
    if (version_line.text.substr(0, prefix.size()) != prefix) {
      in_.fail(version_line.line, "not a legacy VTK file: the first line should read '" +
                                      std::string(prefix) + "x.y'");
    }
    const Token version{version_line.text.substr(prefix.size()), version_line.line};
    const double v = in_.to_real(version, "the VTK file version");
    if (v < 1.0 || v >= 6.0) {
      in_.fail(version.line, "unsupported VTK file version " + quote_text(version.text) +
                                 " (rift reads versions 1.0 to 5.1)");
    }
    in_.take_line();  // the title, free text, possibly empty
    const Token format = in_.take_line();
    if (same_word(format.text, "BINARY")) {
      in_.fail(format.line, "binary VTK files are not supported; save the mesh as ASCII");
    }
    if (!same_word(format.text, "ASCII")) {
      in_.fail(format.line,
               "expected ASCII or BINARY on the third line, found " + quote_text(format.text));
    }
  }

  // A value of an announced list: running out of them is a truncated file, and
  // meeting a keyword means the count was too large.
  Token value(const Token& key, std::size_t done, std::size_t announced) {
    const Token t = in_.next();
    if (t.empty()) {
      in_.fail(t.line, "unexpected end of file in " + std::string(key.text) + " (line " +
                           std::to_string(key.line) + "): " + std::to_string(done) + " of " +
                           std::to_string(announced) + " announced values were read");
    }
    if (std::isalpha(static_cast<unsigned char>(t.text.front())) && !same_word(t.text, "nan") &&
        !same_word(t.text, "inf")) {
      in_.fail(t.line, std::string(key.text) + " (line " + std::to_string(key.line) +
                           ") announces " + std::to_string(announced) + " values, but " +
                           quote_text(t.text) + " comes after " + std::to_string(done));
    }
    return t;
  }

  void read_points(const Token& key) {
    if (!mesh_.points.empty()) in_.fail(key.line, "a second POINTS section");
    const std::size_t n = in_.count("the number of points");
    in_.expect("the data type of the points");
    for (std::size_t k = 0; k < n; ++k) {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        p[c] = in_.to_coordinate(
            value(key, 3 * k + static_cast<std::size_t>(c), 3 * n),
            "coordinate " + std::to_string(c + 1) + " of point " + std::to_string(k));
      }
      grow_for_next_entry(mesh_.points, n);
      mesh_.points.push_back(p);
    }
  }

  CellLists read_cells(const Token& key) {
    CellLists cells;
    cells.header_line = key.line;
    const std::size_t n = in_.count("the number of cells");
    const std::size_t size = in_.count("the size of the cell list");
    if (same_word(in_.peek().text, "OFFSETS")) return read_offset_cells(key, n, size);
    std::size_t used = 0;
    for (std::size_t c = 0; c < n; ++c) {
      const Token count_token = value(key, used, size);
      const std::size_t count = in_.to_count(count_token, "the number of points of a cell");
      if (used + 1 + count > size) {
        in_.fail(count_token.line, std::string(key.text) + " (line " + std::to_string(key.line) +
                                       ") announces a list of " + std::to_string(size) +
                                       " values, but its cells need more");
      }
      for (std::size_t k = 0; k < count; ++k) {
        grow_for_next_entry(cells.connectivity, size);
        cells.connectivity.push_back(
            vtk_point_id(in_, value(key, used + 1 + k, size), mesh_.points.size(), c));
      }
      used += 1 + count;
      cells.offsets.push_back(cells.connectivity.size());
      cells.lines.push_back(count_token.line);
    }
    if (used != size) {
      in_.fail(key.line, std::string(key.text) + " announces a list of " + std::to_string(size) +
                             " values, but its " + std::to_string(n) + " cells hold " +
                             std::to_string(used));
    }
    return cells;
  }

  // File version 5: "CELLS n_offsets n_connectivity", then OFFSETS and
  // CONNECTIVITY arrays, each preceded by its data type.
  CellLists read_offset_cells(const Token& key, std::size_t offsets, std::size_t size) {
    CellLists cells;
    cells.header_line = key.line;
    in_.next();  // OFFSETS
    in_.expect("the data type of the offsets");
    if (offsets == 0) in_.fail(key.line, "the OFFSETS array needs at least one value");
    std::vector<Token> offset_tokens;
    cells.offsets.clear();
    for (std::size_t k = 0; k < offsets; ++k) {
      const Token t = value(key, k, offsets);
      const std::size_t o = in_.to_count(t, "an offset");
      const std::size_t previous = k == 0 ? 0 : cells.offsets.back();
      if ((k == 0 && o != 0) || o < previous || o > size) {
        in_.fail(t.line, "offset " + std::to_string(o) + " is out of order or past the " +
                             std::to_string(size) + " connectivity values");
      }
      cells.offsets.push_back(o);
      offset_tokens.push_back(t);
    }
    if (cells.offsets.back() != size) {
      in_.fail(offset_tokens.back().line, "the last offset should be " + std::to_string(size) +
                                              ", the size of the connectivity array");
    }
    const Token conn = in_.expect("CONNECTIVITY");
    if (!same_word(conn.text, "CONNECTIVITY")) {
      in_.fail(conn.line, "expected CONNECTIVITY, found " + quote_text(conn.text));
    }
    in_.expect("the data type of the connectivity");
    cells.lines.assign(offsets - 1, 0);
    std::size_t cell = 0;
    for (std::size_t k = 0; k < size; ++k) {
      while (cells.offsets[cell + 1] <= k)
        ++cell;
      const Token t = value(conn, k, size);
      if (k == cells.offsets[cell]) cells.lines[cell] = t.line;
      grow_for_next_entry(cells.connectivity, size);
      cells.connectivity.push_back(vtk_point_id(in_, t, mesh_.points.size(), cell));
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cells.lines[c] == 0) cells.lines[c] = offset_tokens[c + 1].line;  // an empty cell
    }
    return cells;
  }

  std::vector<Token> read_types(const Token& key, const CellLists& cells) {
    if (cells.header_line == 0) in_.fail(key.line, "CELL_TYPES before CELLS");
    const Token count = in_.expect("the number of cell types");
    const std::size_t n = in_.to_count(count, "the number of cell types");
    if (n != cells.size()) {
      in_.fail(count.line, "CELL_TYPES announces " + std::to_string(n) +
                               " types, but CELLS (line " + std::to_string(cells.header_line) +
                               ") has " + std::to_string(cells.size()) + " cells");
    }
    std::vector<Token> types;
    types.reserve(n);
    for (std::size_t k = 0; k < n; ++k)
      types.push_back(value(key, k, n));
    return types;
  }

  static std::span<const std::uint32_t> cell_ids(const CellLists& cells, std::size_t c) {
    return std::span(cells.connectivity.data() + cells.offsets[c],
                     cells.offsets[c + 1] - cells.offsets[c]);
  }

  void add_poly_cells(const Token& key, const CellLists& cells) {
    // POLYDATA sections fix the cell kind; reuse the VTK type codes.
    const char* code = same_word(key.text, "POLYGONS")          ? "7"
                       : same_word(key.text, "TRIANGLE_STRIPS") ? "6"
                       : same_word(key.text, "LINES")           ? "4"
                                                                : "2";
    for (std::size_t c = 0; c < cells.size(); ++c) {
      add_vtk_cell(in_, elements_, Token{code, key.line}, cell_ids(cells, c), cells.lines[c], c);
    }
  }

  // VTK 9 writes "METADATA" blocks (INFORMATION, COMPONENT_NAMES) that end at
  // an empty line.
  void skip_metadata() {
    in_.take_line();  // the rest of the METADATA line
    // take_line() returns an empty line at the end of the input too, so this ends.
    while (!in_.take_line().text.empty()) {
    }
  }

  TextCursor in_;
  MeshData mesh_;
  ElementCollector elements_;
};

}  // namespace

MeshData read_vtk_legacy(const std::string& source, std::string_view text) {
  return VtkLegacyReader(source, text).read();
}

}  // namespace rift::io
