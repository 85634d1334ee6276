// Medit .mesh (the INRIA/Mmg ASCII format): a sequence of keywords, each
// followed by a count and that many records. The format is free (a keyword and
// its value may be on separate lines: "Dimension\n3"), so it is read as tokens.
#include <array>
#include <cctype>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "rift/io/element_collector.hpp"
#include "rift/io/readers.hpp"
#include "rift/io/text_cursor.hpp"

namespace rift::io {

namespace {

struct MeditKeyword {
  std::string_view name;
  int vertices;        // vertex indices per record (elements), 0 for other data
  ElementType type;    // for elements that go into the map
  bool element;        // false: lower-dimensional or not an element
  int reals;           // real values per record (not counting `dimension`-sized ones)
  int integers;        // trailing integers per record (references)
  bool per_dimension;  // records are `dimension` reals (normals, tangents)
};

// Sections rift reads or skips. Each record's size must be known to skip it,
// because a count alone does not say where the section ends.
constexpr std::array<MeditKeyword, 17> kKeywords = {{
    {"Triangles", 3, ElementType::Polygon, true, 0, 1, false},
    {"Quadrilaterals", 4, ElementType::Polygon, true, 0, 1, false},
    {"Tetrahedra", 4, ElementType::Tetra, true, 0, 1, false},
    {"Hexahedra", 8, ElementType::Hexa, true, 0, 1, false},
    {"Prisms", 6, ElementType::Wedge, true, 0, 1, false},
    {"Edges", 2, ElementType::Polygon, false, 0, 1, false},
    {"Corners", 1, ElementType::Polygon, false, 0, 0, false},
    {"RequiredVertices", 1, ElementType::Polygon, false, 0, 0, false},
    {"Ridges", 0, ElementType::Polygon, false, 0, 1, false},
    {"RequiredEdges", 0, ElementType::Polygon, false, 0, 1, false},
    {"RequiredTriangles", 0, ElementType::Polygon, false, 0, 1, false},
    {"RequiredQuadrilaterals", 0, ElementType::Polygon, false, 0, 1, false},
    {"RequiredTetrahedra", 0, ElementType::Polygon, false, 0, 1, false},
    {"Normals", 0, ElementType::Polygon, false, 0, 0, true},
    {"Tangents", 0, ElementType::Polygon, false, 0, 0, true},
    {"NormalAtVertices", 0, ElementType::Polygon, false, 0, 2, false},
    {"TangentAtVertices", 0, ElementType::Polygon, false, 0, 2, false},
}};

const MeditKeyword* find_keyword(std::string_view name) {
  for (const MeditKeyword& k : kKeywords) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

bool is_keyword(std::string_view word) {
  return find_keyword(word) != nullptr || word == "Vertices" || word == "End" ||
         word == "Dimension" || word == "MeshVersionFormatted";
}

class MeditReader {
 public:
  MeditReader(const std::string& source, std::string_view text) : in_(source, text, 1, '#') {
    mesh_.source = source;
  }

  MeshData read() {
    const Token first = in_.next();
    if (first.text != "MeshVersionFormatted") {
      in_.fail(first.line,
               "not a Medit mesh: expected MeshVersionFormatted, found " + quote_text(first.text));
    }
    const Token version = in_.expect("the Medit format version");
    if (version.text != "1" && version.text != "2") {
      in_.fail(version.line, "unsupported Medit format version " + quote_text(version.text) +
                                 " (rift reads versions 1 and 2 in ASCII)");
    }
    bool ended = false;
    while (!ended) {
      const Token key = in_.next();
      if (key.empty()) in_.fail(key.line, "unexpected end of file: the mesh has no End keyword");
      if (key.text == "End") {
        ended = true;
      } else if (key.text == "Dimension") {
        const Token d = in_.expect("the dimension");
        const std::int64_t dim = in_.to_integer(d, "the dimension");
        if (dim != 2 && dim != 3) in_.fail(d.line, "unsupported dimension " + quote_text(d.text));
        dimension_ = static_cast<int>(dim);
      } else if (key.text == "Vertices") {
        read_vertices(key);
      } else if (const MeditKeyword* k = find_keyword(key.text)) {
        read_records(key, *k);
      } else if (std::isalpha(static_cast<unsigned char>(key.text.front()))) {
        in_.fail(key.line, "unknown Medit keyword " + quote_text(key.text));
      } else {
        in_.fail(key.line, "expected a Medit keyword, found " + quote_text(key.text) +
                               " (does a section hold more entries than its count announces?)");
      }
    }
    if (!in_.at_end()) {
      const Token t = in_.next();
      in_.fail(t.line, "unexpected " + quote_text(t.text) + " after End");
    }
    elements_.finish(mesh_, 0);
    return std::move(mesh_);
  }

 private:
  // The next value of record `done` of a section announcing `announced`.
  Token value(const Token& key, std::size_t done, std::size_t announced) {
    const Token t = in_.next();
    if (t.empty()) {
      in_.fail(t.line, "unexpected end of file in " + std::string(key.text) + ": " +
                           std::to_string(done) + " of the " + std::to_string(announced) +
                           " announced entries were read");
    }
    if (is_keyword(t.text)) {
      in_.fail(t.line, std::string(key.text) + " (line " + std::to_string(key.line) +
                           ") announces " + std::to_string(announced) + " entries but holds " +
                           std::to_string(done));
    }
    return t;
  }

  void read_vertices(const Token& key) {
    if (dimension_ == 0) in_.fail(key.line, "Vertices before Dimension");
    if (!mesh_.points.empty()) in_.fail(key.line, "a second Vertices section");
    const std::size_t n = in_.count("the number of vertices");
    for (std::size_t k = 0; k < n; ++k) {
      Vec3 p = Vec3::Zero();
      for (int c = 0; c < dimension_; ++c) {
        const std::string what =
            "coordinate " + std::to_string(c + 1) + " of vertex " + std::to_string(k + 1);
        p[c] = in_.to_coordinate(value(key, k, n), what);
      }
      in_.to_integer(value(key, k, n), "the reference of vertex " + std::to_string(k + 1));
      grow_for_next_entry(mesh_.points, n);
      mesh_.points.push_back(p);
    }
  }

  void read_records(const Token& key, const MeditKeyword& k) {
    // Normals and tangents hold `dimension` values per record: before
    // Dimension a record would hold none, and a huge count would loop without
    // reading anything.
    if (k.per_dimension && dimension_ == 0) {
      in_.fail(key.line, std::string(k.name) + " before Dimension");
    }
    const std::size_t n = in_.count("the number of " + std::string(k.name));
    std::array<std::uint32_t, 8> v{};
    for (std::size_t r = 0; r < n; ++r) {
      int line = 0;
      for (int i = 0; i < k.vertices; ++i) {
        const Token t = value(key, r, n);
        if (i == 0) line = t.line;
        v[static_cast<std::size_t>(i)] = vertex(t, key, r);
      }
      const int reals = k.reals + (k.per_dimension ? dimension_ : 0);
      for (int i = 0; i < reals; ++i)
        in_.to_real(value(key, r, n), "a value of " + std::string(k.name));
      std::optional<std::int64_t> reference;
      for (int i = 0; i < k.integers; ++i) {
        const std::int64_t ref =
            in_.to_integer(value(key, r, n), "an integer of " + std::string(k.name));
        if (i == 0) reference = ref;
      }
      if (!k.element) {
        if (k.vertices >= 2) elements_.ignore_lower_dimensional();
        continue;
      }
      if (element_dimension(k.type) == 3 && dimension_ != 3) {
        in_.fail(line,
                 std::string(k.name) + " in a mesh of dimension " + std::to_string(dimension_));
      }
      elements_.add(k.type, std::span(v.data(), static_cast<std::size_t>(k.vertices)), line,
                    reference);
    }
  }

  std::uint32_t vertex(const Token& t, const Token& key, std::size_t record) {
    const std::int64_t index = in_.to_integer(t, "a vertex index");
    if (index < 1 || index > static_cast<std::int64_t>(mesh_.points.size())) {
      in_.fail(t.line, std::string(key.text) + " entry " + std::to_string(record + 1) +
                           " refers to vertex " + std::to_string(index) + ", but the mesh has " +
                           std::to_string(mesh_.points.size()) + " vertices (numbered from 1)");
    }
    return static_cast<std::uint32_t>(index - 1);
  }

  TextCursor in_;
  MeshData mesh_;
  ElementCollector elements_;
  int dimension_ = 0;
};

}  // namespace

MeshData read_medit(const std::string& source, std::string_view text) {
  return MeditReader(source, text).read();
}

}  // namespace rift::io
