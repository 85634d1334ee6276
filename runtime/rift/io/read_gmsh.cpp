// Gmsh .msh in its three ASCII dialects and the binary forms of v2.2 and v4.1.
// v1 and v2.2 share the node layout ("tag x y z" per line) and differ in the
// element header; v4.1 groups nodes and elements in entity blocks. Node tags
// are arbitrary ids (sparse, any order), so they are mapped to 0-based indices
// as they are read.
//
// Binary files keep the ASCII section markers ($Nodes ... $EndNodes) and, in
// v2.2, the counts after them; the data between is little- or big-endian as the
// integer 1 after the format line says. v2.2 writes 4-byte ints and doubles;
// v4.1 writes ints, size_t (of the data size in the format line) and doubles.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "rift/io/element_collector.hpp"
#include "rift/io/readers.hpp"
#include "rift/io/text_cursor.hpp"

namespace rift::io {

namespace {

struct GmshType {
  int nodes;         // 0: unknown or unsupported
  bool lower;        // a line or point: ignored
  ElementType type;  // when !lower
  const char* name;
};

GmshType gmsh_type(std::int64_t code) {
  switch (code) {
    case 1:
      return {2, true, ElementType::Polygon, "line"};
    case 15:
      return {1, true, ElementType::Polygon, "point"};
    case 2:
      return {3, false, ElementType::Polygon, "triangle"};
    case 3:
      return {4, false, ElementType::Polygon, "quadrangle"};
    case 4:
      return {4, false, ElementType::Tetra, "tetrahedron"};
    case 5:
      return {8, false, ElementType::Hexa, "hexahedron"};
    case 6:
      return {6, false, ElementType::Wedge, "prism"};
    case 7:
      return {5, false, ElementType::Pyramid, "pyramid"};
    default:
      return {0, false, ElementType::Polygon, nullptr};
  }
}

enum class Dialect { kV1, kV2, kV4 };

// Node tags to 0-based indices. Gmsh numbers nodes 1..n in practice, so a flat
// table indexed by tag (4 bytes a node) serves them; a tag far beyond the
// nodes read so far goes to a hash map, so the table never outgrows the data.
class TagIndex {
 public:
  /// False if `tag` is already there.
  bool insert(std::int64_t tag, std::uint32_t index) {
    if (tag >= 0 && static_cast<std::uint64_t>(tag) < dense_limit()) {
      const auto t = static_cast<std::size_t>(tag);
      if (t >= dense_.size()) dense_.resize(std::max(t + 1, 2 * dense_.size()), kNone);
      if (dense_[t] != kNone) return false;
      dense_[t] = index;
      ++count_;
      return true;
    }
    if (find(tag) != kNone) return false;
    sparse_.emplace(tag, index);
    ++count_;
    return true;
  }
  /// kNone if `tag` is not there.
  std::uint32_t find(std::int64_t tag) const {
    if (tag >= 0 && static_cast<std::uint64_t>(tag) < dense_.size())
      return dense_[static_cast<std::size_t>(tag)];
    const auto it = sparse_.find(tag);
    return it == sparse_.end() ? kNone : it->second;
  }
  static constexpr std::uint32_t kNone = ~0u;

 private:
  std::uint64_t dense_limit() const { return 2 * std::uint64_t{count_} + 1024; }

  std::vector<std::uint32_t> dense_;
  std::unordered_map<std::int64_t, std::uint32_t> sparse_;
  std::size_t count_ = 0;
};

class GmshReader {
 public:
  GmshReader(const std::string& source, std::string_view text) : in_(source, text) {
    mesh_.source = source;
  }

  MeshData read() {
    const Token first = in_.peek();
    if (first.text == "$NOD") {
      dialect_ = Dialect::kV1;
    } else if (first.text == "$MeshFormat") {
      read_format(in_.next());
    } else {
      in_.fail(first.line,
               "not a Gmsh file: expected $MeshFormat or $NOD, found " + quote_text(first.text));
    }
    while (!in_.at_end()) {
      const Token header = in_.next();
      if (header.text.empty() || header.text.front() != '$') {
        in_.fail(header.line, "expected a section such as $Nodes or $Elements, found " +
                                  quote_text(header.text));
      }
      const bool v1 = dialect_ == Dialect::kV1;
      if (header.text == (v1 ? "$NOD" : "$Nodes")) {
        saw_nodes_ = true;
        if (binary_) {
          dialect_ == Dialect::kV4 ? read_nodes_v4_binary(header) : read_nodes_v2_binary(header);
        } else {
          dialect_ == Dialect::kV4 ? read_nodes_v4(header) : read_nodes_v12(header);
        }
      } else if (header.text == (v1 ? "$ELM" : "$Elements")) {
        if (binary_) {
          dialect_ == Dialect::kV4 ? read_elements_v4_binary(header)
                                   : read_elements_v2_binary(header);
        } else {
          dialect_ == Dialect::kV4 ? read_elements_v4(header) : read_elements_v12(header);
        }
      } else if (dialect_ == Dialect::kV4 && header.text == "$Entities") {
        binary_ ? read_entities_v4_binary(header) : read_entities_v4(header);
      } else {
        skip_section(header);
      }
    }
    if (!saw_nodes_)
      in_.fail(0, "the file has no " + std::string(dialect_ == Dialect::kV1 ? "$NOD" : "$Nodes") +
                      " section");
    elements_.finish(mesh_, elements_line_);
    return std::move(mesh_);
  }

 private:
  void read_format(const Token& header) {
    const Token version = in_.expect("the Gmsh format version");
    const std::int64_t file_type = in_.integer("the file type (0 for ASCII, 1 for binary)");
    const Token data_size = in_.expect("the data size");
    if (file_type != 0 && file_type != 1)
      in_.fail(version.line, "unknown Gmsh file type " + std::to_string(file_type));
    if (file_type == 1) {
      binary_ = true;
      const std::int64_t size = in_.to_integer(data_size, "the data size");
      if (size != 4 && size != 8) {
        in_.fail(data_size.line, "data size " + std::to_string(size) + " is not 4 or 8");
      }
      size_bytes_ = static_cast<int>(size);
      in_.skip_line();
      // The integer 1, written in the file's byte order.
      const std::string_view one = in_.take_bytes(4, "the binary marker (the integer 1)");
      if (one == std::string_view("\1\0\0\0", 4)) {
        big_endian_ = false;
      } else if (one == std::string_view("\0\0\0\1", 4)) {
        big_endian_ = true;
      } else {
        in_.fail(version.line + 1,
                 "the binary marker after the format line is not the integer 1 (" +
                     quote_text(one) + "): the file is damaged or not binary");
      }
    }
    const double v = in_.to_real(version, "the Gmsh format version");
    if (v >= 2.0 && v < 3.0) {
      dialect_ = Dialect::kV2;
    } else if (version.text == "4.1") {
      dialect_ = Dialect::kV4;
    } else {
      in_.fail(version.line, "unsupported Gmsh format version " + std::string(version.text) +
                                 " (rift reads 1, 2.x and 4.1 ASCII)");
    }
    const Token end = in_.next();
    if (end.text != "$EndMeshFormat") {
      in_.fail(end.line, "expected $EndMeshFormat after the format line (line " +
                             std::to_string(header.line + 1) + "), found " + quote_text(end.text));
    }
  }

  std::string end_of(const Token& header) const {
    const std::string_view name = header.text.substr(1);
    return (dialect_ == Dialect::kV1 ? "$END" : "$End") + std::string(name);
  }

  void skip_section(const Token& header) {
    const std::string end = end_of(header);
    if (binary_) {
      // Binary data has no tokens: look for the end marker itself.
      if (!in_.skip_past(end)) {
        in_.fail(in_.line(), "unexpected end of file: section " + std::string(header.text) +
                                 " (line " + std::to_string(header.line) + ") has no " + end);
      }
      return;
    }
    for (Token t = in_.next(); t.text != end; t = in_.next()) {
      if (t.empty()) {
        in_.fail(t.line, "unexpected end of file: section " + std::string(header.text) + " (line " +
                             std::to_string(header.line) + ") has no " + end);
      }
    }
  }

  // The first token of entry `done` (0-based) of `announced`, with the two ways
  // a count can lie: the file ends, or the section ends early.
  Token entry(const Token& header, std::size_t done, std::size_t announced, const char* noun) {
    const Token t = in_.next();
    if (t.empty()) {
      in_.fail(t.line, "unexpected end of file in " + std::string(header.text) + ": " +
                           std::to_string(done) + " of the " + std::to_string(announced) +
                           " announced " + noun + " were read");
    }
    if (t.text.front() == '$') {
      in_.fail(t.line, "section " + std::string(header.text) + " announces " +
                           std::to_string(announced) + " " + noun + " but holds " +
                           std::to_string(done));
    }
    return t;
  }

  // A further field of the entry that started on `line`: entries are one line each.
  Token field(int line, const std::string& what) {
    const Token t = in_.next_on_line();
    if (t.empty()) in_.fail(line, "line ends early, expected " + what);
    return t;
  }

  void end_of_entry(int line) {
    const Token extra = in_.next_on_line();
    if (!extra.empty())
      in_.fail(line, "unexpected " + quote_text(extra.text) + " at the end of the line");
  }

  void expect_end(const Token& header, std::size_t announced, std::size_t done, const char* noun) {
    const std::string end = end_of(header);
    const Token t = in_.next();
    if (t.text == end) return;
    if (t.empty()) {
      in_.fail(t.line, "unexpected end of file: section " + std::string(header.text) + " (line " +
                           std::to_string(header.line) + ") has no " + end);
    }
    if (t.text.front() == '$')
      in_.fail(t.line, "expected " + end + ", found " + quote_text(t.text));
    in_.fail(t.line, "section " + std::string(header.text) + " holds more than the " +
                         std::to_string(announced) + " " + noun + " it announces (" +
                         std::to_string(done) + " expected, then " + end + ")");
  }

  void add_node(const Token& tag_token, const Vec3& p) {
    add_node(in_.to_integer(tag_token, "a node tag"), tag_token.line, p);
  }
  void add_node(std::int64_t tag, int line, const Vec3& p) {
    if (mesh_.points.size() >= static_cast<std::size_t>(INT32_MAX)) {
      in_.fail(line, "more nodes than a mesh can hold (2^31 - 1)");
    }
    if (!node_index_.insert(tag, static_cast<std::uint32_t>(mesh_.points.size())))
      in_.fail(line, "node " + std::to_string(tag) + " is defined twice");
    grow_for_next_entry(mesh_.points, announced_nodes_);
    mesh_.points.push_back(p);
  }

  Vec3 coordinates(int line, std::int64_t node) {
    Vec3 p;
    static constexpr const char* kAxis[] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
      const std::string what =
          std::string("the ") + kAxis[c] + " coordinate of node " + std::to_string(node);
      p[c] = in_.to_coordinate(field(line, what), what);
    }
    return p;
  }

  void read_nodes_v12(const Token& header) {
    const std::size_t n = in_.count("the number of nodes");
    announced_nodes_ = n;
    for (std::size_t k = 0; k < n; ++k) {
      const Token tag = entry(header, k, n, "nodes");
      const Vec3 p = coordinates(tag.line, in_.to_integer(tag, "a node tag"));
      end_of_entry(tag.line);
      add_node(tag, p);
    }
    expect_end(header, n, n, "nodes");
  }

  void read_nodes_v4(const Token& header) {
    const std::size_t blocks = in_.count("the number of node blocks");
    const std::size_t n = in_.count("the number of nodes");
    in_.integer("the smallest node tag");
    in_.integer("the largest node tag");
    announced_nodes_ = n;
    std::size_t done = 0;
    std::vector<Token> tags;
    for (std::size_t b = 0; b < blocks; ++b) {
      const Token dim_token = entry(header, b, blocks, "node blocks");
      const std::int64_t entity_dim = in_.to_integer(dim_token, "an entity dimension");
      in_.to_integer(field(dim_token.line, "an entity tag"), "an entity tag");
      const std::int64_t parametric =
          in_.to_integer(field(dim_token.line, "the parametric flag"), "the parametric flag");
      const std::size_t in_block =
          in_.to_count(field(dim_token.line, "the number of nodes"), "the number of nodes");
      end_of_entry(dim_token.line);
      if (done + in_block > n) {
        in_.fail(dim_token.line, "section $Nodes announces " + std::to_string(n) +
                                     " nodes but its blocks hold more");
      }
      tags.clear();
      for (std::size_t k = 0; k < in_block; ++k) {
        tags.push_back(entry(header, done + k, n, "nodes"));
        end_of_entry(tags.back().line);
      }
      // Parametric nodes carry entity_dim extra coordinates (u, v, w) that a
      // mesh does not need.
      const std::int64_t extra = parametric != 0 ? entity_dim : 0;
      for (const Token& tag : tags) {
        const Token x = entry(header, done, n, "nodes");
        const std::int64_t id = in_.to_integer(tag, "a node tag");
        Vec3 p;
        p[0] = in_.to_coordinate(x, "the x coordinate of node " + std::to_string(id));
        for (int c = 1; c < 3; ++c) {
          const std::string what = std::string("the ") + (c == 1 ? "y" : "z") +
                                   " coordinate of node " + std::to_string(id);
          p[c] = in_.to_coordinate(field(x.line, what), what);
        }
        for (std::int64_t e = 0; e < extra; ++e)
          in_.to_real(field(x.line, "a parametric coordinate"), "a parametric coordinate");
        end_of_entry(x.line);
        add_node(tag, p);
        ++done;
      }
    }
    if (done != n) {
      in_.fail(header.line + 1, "section $Nodes announces " + std::to_string(n) +
                                    " nodes but its blocks hold " + std::to_string(done));
    }
    expect_end(header, blocks, blocks, "node blocks");
  }

  std::uint32_t node(const Token& t, std::int64_t element) {
    return node(in_.to_integer(t, "a node tag"), t.line, element);
  }
  std::uint32_t node(std::int64_t tag, int line, std::int64_t element) {
    const std::uint32_t index = node_index_.find(tag);
    if (index == TagIndex::kNone) {
      in_.fail(line, "element " + std::to_string(element) + " refers to node " +
                         std::to_string(tag) + ", which is not defined");
    }
    return index;
  }

  GmshType element_type(const Token& t) {
    return element_type(in_.to_integer(t, "an element type"), t.line);
  }
  GmshType element_type(std::int64_t code, int line) {
    const GmshType type = gmsh_type(code);
    if (type.nodes == 0) {
      in_.fail(line, "unknown or unsupported element type " + std::to_string(code) +
                         " (rift reads Gmsh types 1, 2, 3, 4, 5, 6, 7 and 15: linear elements)");
    }
    return type;
  }

  // Reads the element's node tags (the rest of its line) and keeps it.
  void read_element_nodes(const GmshType& type, std::int64_t id, int line) {
    std::array<std::uint32_t, 8> v{};
    for (int k = 0; k < type.nodes; ++k) {
      const std::string what = "node " + std::to_string(k + 1) + " of " + type.name + " " +
                               std::to_string(id) + " (" + std::to_string(type.nodes) + " nodes)";
      v[static_cast<std::size_t>(k)] = node(field(line, what), id);
    }
    end_of_entry(line);
    keep_element(type, v, line);
  }

  void keep_element(const GmshType& type, std::array<std::uint32_t, 8> v, int line) {
    if (type.lower) {
      elements_.ignore_lower_dimensional();
      return;
    }
    if (type.type == ElementType::Wedge) {
      // Gmsh's prism has its first triangle's normal pointing into the
      // element, VTK's wedge (our convention) out of it: reverse both triangles.
      v = {v[0], v[2], v[1], v[3], v[5], v[4], 0, 0};
    }
    elements_.add(type.type, std::span(v.data(), static_cast<std::size_t>(type.nodes)), line,
                  physical_);
  }

  void read_elements_v12(const Token& header) {
    elements_line_ = header.line;
    const std::size_t n = in_.count("the number of elements");
    for (std::size_t k = 0; k < n; ++k) {
      const Token number = entry(header, k, n, "elements");
      const std::int64_t id = in_.to_integer(number, "an element number");
      const GmshType type = element_type(field(number.line, "an element type"));
      if (dialect_ == Dialect::kV1) {
        physical_ = in_.to_integer(field(number.line, "a physical region"), "a physical region");
        in_.to_integer(field(number.line, "an elementary region"), "an elementary region");
        const Token count = field(number.line, "the number of nodes");
        const std::size_t nodes = in_.to_count(count, "the number of nodes");
        if (nodes != static_cast<std::size_t>(type.nodes)) {
          in_.fail(count.line, std::string(type.name) + " " + std::to_string(id) + " has " +
                                   std::to_string(nodes) + " nodes, expected " +
                                   std::to_string(type.nodes));
        }
      } else {
        const std::size_t tags =
            in_.to_count(field(number.line, "the number of tags"), "the number of tags");
        // The first tag is the physical group.
        physical_.reset();
        for (std::size_t t = 0; t < tags; ++t) {
          const std::int64_t value = in_.to_integer(field(number.line, "a tag"), "a tag");
          if (t == 0) physical_ = value;
        }
      }
      read_element_nodes(type, id, number.line);
    }
    expect_end(header, n, n, "elements");
  }

  // $Entities (v4.1 ASCII): the physical groups of each geometric entity.
  // Elements name their entity (dimension, tag) in their block's header; the
  // entity's first physical tag is their group, as the first tag is in v2.
  void read_entities_v4(const Token& header) {
    static constexpr const char* kKinds[] = {"points", "curves", "surfaces", "volumes"};
    std::array<std::size_t, 4> counts{};
    for (int dim = 0; dim < 4; ++dim)
      counts[static_cast<std::size_t>(dim)] =
          in_.count(std::string("the number of ") + kKinds[dim] + " in $Entities");
    for (int dim = 0; dim < 4; ++dim) {
      const std::size_t n = counts[static_cast<std::size_t>(dim)];
      for (std::size_t k = 0; k < n; ++k) {
        const Token tag_token = entry(header, k, n, kKinds[dim]);
        const std::int64_t tag = in_.to_integer(tag_token, "an entity tag");
        const int line = tag_token.line;
        // A point has its coordinates, the others their bounding box.
        for (int c = 0; c < (dim == 0 ? 3 : 6); ++c)
          in_.to_real(field(line, "a coordinate of the entity's box"), "a coordinate");
        const std::size_t physicals =
            in_.to_count(field(line, "the number of physical tags"), "the number of physical tags");
        for (std::size_t t = 0; t < physicals; ++t) {
          const std::int64_t physical =
              in_.to_integer(field(line, "a physical tag"), "a physical tag");
          if (t == 0) entity_physical_[{dim, tag}] = physical;
        }
        if (dim > 0) {
          const std::size_t bounding = in_.to_count(field(line, "the number of bounding entities"),
                                                    "the number of bounding entities");
          for (std::size_t b = 0; b < bounding; ++b)
            in_.to_integer(field(line, "a bounding entity's tag"), "an entity tag");
        }
        end_of_entry(line);
      }
    }
    expect_end(header, counts[3], counts[3], kKinds[3]);
  }

  // The physical group of the elements of entity (dim, tag), if it has one.
  std::optional<std::int64_t> physical_of_entity(std::int64_t dim, std::int64_t tag) const {
    const auto it = entity_physical_.find({dim, tag});
    if (it == entity_physical_.end()) return std::nullopt;
    return it->second;
  }

  void read_elements_v4(const Token& header) {
    elements_line_ = header.line;
    const std::size_t blocks = in_.count("the number of element blocks");
    const std::size_t n = in_.count("the number of elements");
    in_.integer("the smallest element tag");
    in_.integer("the largest element tag");
    std::size_t done = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const Token dim_token = entry(header, b, blocks, "element blocks");
      const std::int64_t entity_dim = in_.to_integer(dim_token, "an entity dimension");
      const std::int64_t entity =
          in_.to_integer(field(dim_token.line, "an entity tag"), "an entity tag");
      physical_ = physical_of_entity(entity_dim, entity);
      const GmshType type = element_type(field(dim_token.line, "an element type"));
      const std::size_t in_block =
          in_.to_count(field(dim_token.line, "the number of elements"), "the number of elements");
      end_of_entry(dim_token.line);
      if (done + in_block > n) {
        in_.fail(dim_token.line, "section $Elements announces " + std::to_string(n) +
                                     " elements but its blocks hold more");
      }
      for (std::size_t k = 0; k < in_block; ++k) {
        const Token tag = entry(header, done, n, "elements");
        read_element_nodes(type, in_.to_integer(tag, "an element tag"), tag.line);
        ++done;
      }
    }
    if (done != n) {
      in_.fail(header.line + 1, "section $Elements announces " + std::to_string(n) +
                                    " elements but its blocks hold " + std::to_string(done));
    }
    expect_end(header, blocks, blocks, "element blocks");
  }

  // ---- binary data ----

  std::uint64_t unsigned_bytes(int bytes, const char* what) {
    const std::string_view b = in_.take_bytes(static_cast<std::size_t>(bytes), what);
    std::uint64_t value = 0;
    for (int k = 0; k < bytes; ++k) {
      const auto byte = static_cast<std::size_t>(big_endian_ ? k : bytes - 1 - k);
      value = (value << 8) | static_cast<unsigned char>(b[byte]);
    }
    return value;
  }
  std::int64_t int32(const char* what) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(unsigned_bytes(4, what)));
  }
  // A size_t of the data size; counts and tags beyond 2^63 are errors.
  std::int64_t size_value(const char* what) {
    const std::uint64_t v = unsigned_bytes(size_bytes_, what);
    if (v > static_cast<std::uint64_t>(INT64_MAX)) {
      in_.fail(in_.line(),
               std::string(what) + " is out of range (byte " + std::to_string(in_.offset()) + ")");
    }
    return static_cast<std::int64_t>(v);
  }
  std::size_t binary_count(std::int64_t value, const char* what) {
    if (value < 0 || value > INT32_MAX) {
      in_.fail(in_.line(), std::string(what) + " " + std::to_string(value) +
                               " is negative or too large (byte " + std::to_string(in_.offset()) +
                               ")");
    }
    return static_cast<std::size_t>(value);
  }
  Vec3 binary_point(std::int64_t tag) {
    Vec3 p;
    static constexpr const char* kAxis[] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
      const double v = std::bit_cast<double>(unsigned_bytes(8, "a coordinate"));
      p[c] = in_.check_coordinate(
          v, in_.line(),
          std::string("the ") + kAxis[c] + " coordinate of node " + std::to_string(tag));
    }
    return p;
  }
  // Fails unless `entries` entries of at least `bytes_each` bytes can still follow.
  void check_room(std::size_t entries, std::size_t bytes_each, const Token& header,
                  const char* noun) {
    if (entries > in_.bytes_left() / bytes_each) {
      in_.fail(in_.line(), "section " + std::string(header.text) + " announces " +
                               std::to_string(entries) + " " + noun +
                               ", more than the rest of the file can hold");
    }
  }

  void read_nodes_v2_binary(const Token& header) {
    const std::size_t n = in_.count("the number of nodes");
    in_.skip_line();
    check_room(n, 4 + 3 * 8, header, "nodes");
    announced_nodes_ = n;
    for (std::size_t k = 0; k < n; ++k) {
      const std::int64_t tag = int32("a node tag");
      add_node(tag, in_.line(), binary_point(tag));
    }
    expect_end(header, n, n, "nodes");
  }

  void read_elements_v2_binary(const Token& header) {
    elements_line_ = header.line;
    const std::size_t n = in_.count("the number of elements");
    in_.skip_line();
    std::size_t done = 0;
    while (done < n) {
      // A block header: type, number of elements that follow, tags per element.
      const int line = in_.line();
      const GmshType type = element_type(int32("an element type"), line);
      const std::int64_t follow = int32("the number of elements in the block");
      const std::int64_t tags = int32("the number of tags");
      if (follow <= 0 || static_cast<std::size_t>(follow) > n - done) {
        in_.fail(line, "an element block of " + std::to_string(follow) + " elements in " +
                           std::string(header.text) + ", where " + std::to_string(n - done) +
                           " of the announced " + std::to_string(n) + " remain");
      }
      if (tags < 0) in_.fail(line, "negative number of tags " + std::to_string(tags));
      const auto entry_bytes =
          4 * (1 + static_cast<std::size_t>(tags) + static_cast<std::size_t>(type.nodes));
      check_room(static_cast<std::size_t>(follow), entry_bytes, header, "elements");
      for (std::int64_t k = 0; k < follow; ++k) {
        const std::int64_t id = int32("an element number");
        // The first tag is the physical group, as in the ASCII file.
        physical_.reset();
        for (std::int64_t t = 0; t < tags; ++t) {
          const std::int64_t value = int32("an element tag");
          if (t == 0) physical_ = value;
        }
        std::array<std::uint32_t, 8> v{};
        for (int m = 0; m < type.nodes; ++m)
          v[static_cast<std::size_t>(m)] = node(int32("a node tag"), in_.line(), id);
        keep_element(type, v, in_.line());
      }
      done += static_cast<std::size_t>(follow);
    }
    expect_end(header, n, n, "elements");
  }

  // $Entities (v4.1 binary): the ASCII section's fields, with size_t counts
  // and int tags; only each entity's first physical tag is kept.
  void read_entities_v4_binary(const Token& header) {
    in_.skip_line();
    std::array<std::size_t, 4> counts{};
    for (std::size_t& count : counts)
      count = binary_count(size_value("the number of entities"), "the number of entities");
    const auto size_bytes = static_cast<std::size_t>(size_bytes_);
    for (int dim = 0; dim < 4; ++dim) {
      const std::size_t n = counts[static_cast<std::size_t>(dim)];
      // A point has its coordinates, the others their bounding box, then the
      // count of physical tags (and of bounding entities beyond points).
      const std::size_t fixed_bytes = 4 + (dim == 0 ? 24 : 48) + size_bytes * (dim == 0 ? 1 : 2);
      check_room(n, fixed_bytes, header, "entities");
      for (std::size_t k = 0; k < n; ++k) {
        const std::int64_t tag = int32("an entity tag");
        in_.take_bytes(dim == 0 ? 24 : 48, "the entity's coordinates or bounding box");
        const std::size_t physicals =
            binary_count(size_value("the number of physical tags"), "the number of physical tags");
        check_room(physicals, 4, header, "physical tags");
        for (std::size_t t = 0; t < physicals; ++t) {
          const std::int64_t physical = int32("a physical tag");
          if (t == 0) entity_physical_[{dim, tag}] = physical;
        }
        if (dim > 0) {
          const std::size_t bounding = binary_count(size_value("the number of bounding entities"),
                                                    "the number of bounding entities");
          check_room(bounding, 4, header, "bounding entities");
          in_.take_bytes(4 * bounding, "the bounding entities' tags");
        }
      }
    }
    expect_end(header, counts[3], counts[3], "volumes");
  }

  void read_nodes_v4_binary(const Token& header) {
    in_.skip_line();
    const std::size_t blocks = binary_count(size_value("the number of node blocks"), "node blocks");
    const std::size_t n = binary_count(size_value("the number of nodes"), "the number of nodes");
    size_value("the smallest node tag");
    size_value("the largest node tag");
    check_room(n, static_cast<std::size_t>(size_bytes_) + 24, header, "nodes");
    announced_nodes_ = n;
    std::size_t done = 0;
    std::vector<std::int64_t> tags;
    for (std::size_t b = 0; b < blocks; ++b) {
      const int line = in_.line();
      const std::int64_t entity_dim = int32("an entity dimension");
      int32("an entity tag");
      const std::int64_t parametric = int32("the parametric flag");
      const std::size_t in_block =
          binary_count(size_value("the number of nodes"), "nodes in a block");
      if (in_block > n - done) {
        in_.fail(line, "section $Nodes announces " + std::to_string(n) +
                           " nodes but its blocks hold more");
      }
      if (entity_dim < 0 || entity_dim > 3) {
        in_.fail(line, "entity dimension " + std::to_string(entity_dim) + " is not 0 to 3");
      }
      tags.clear();
      for (std::size_t k = 0; k < in_block; ++k)
        tags.push_back(size_value("a node tag"));
      const std::int64_t extra = parametric != 0 ? entity_dim : 0;
      for (const std::int64_t tag : tags) {
        const Vec3 p = binary_point(tag);
        in_.take_bytes(8 * static_cast<std::size_t>(extra), "parametric coordinates");
        add_node(tag, in_.line(), p);
      }
      done += in_block;
    }
    if (done != n) {
      in_.fail(header.line + 1, "section $Nodes announces " + std::to_string(n) +
                                    " nodes but its blocks hold " + std::to_string(done));
    }
    expect_end(header, blocks, blocks, "node blocks");
  }

  void read_elements_v4_binary(const Token& header) {
    elements_line_ = header.line;
    in_.skip_line();
    const std::size_t blocks =
        binary_count(size_value("the number of element blocks"), "element blocks");
    const std::size_t n =
        binary_count(size_value("the number of elements"), "the number of elements");
    size_value("the smallest element tag");
    size_value("the largest element tag");
    std::size_t done = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const int line = in_.line();
      const std::int64_t entity_dim = int32("an entity dimension");
      const std::int64_t entity = int32("an entity tag");
      physical_ = physical_of_entity(entity_dim, entity);
      const GmshType type = element_type(int32("an element type"), line);
      const std::size_t in_block =
          binary_count(size_value("the number of elements"), "elements in a block");
      if (in_block > n - done) {
        in_.fail(line, "section $Elements announces " + std::to_string(n) +
                           " elements but its blocks hold more");
      }
      check_room(in_block,
                 static_cast<std::size_t>(size_bytes_) * (1 + static_cast<std::size_t>(type.nodes)),
                 header, "elements");
      for (std::size_t k = 0; k < in_block; ++k) {
        const std::int64_t id = size_value("an element tag");
        std::array<std::uint32_t, 8> v{};
        for (int m = 0; m < type.nodes; ++m)
          v[static_cast<std::size_t>(m)] = node(size_value("a node tag"), in_.line(), id);
        keep_element(type, v, in_.line());
      }
      done += in_block;
    }
    if (done != n) {
      in_.fail(header.line + 1, "section $Elements announces " + std::to_string(n) +
                                    " elements but its blocks hold " + std::to_string(done));
    }
    expect_end(header, blocks, blocks, "element blocks");
  }

  TextCursor in_;
  bool binary_ = false;
  bool big_endian_ = false;
  int size_bytes_ = 8;
  Dialect dialect_ = Dialect::kV2;
  MeshData mesh_;
  ElementCollector elements_;
  TagIndex node_index_;
  // The count of the $Nodes header: mesh_.points grows with the nodes read,
  // never past it (grow_for_next_entry), so a lying count reserves nothing.
  std::size_t announced_nodes_ = 0;
  int elements_line_ = 0;
  bool saw_nodes_ = false;
  // Physical group of the element being read (v1, v2: its first tag; v4:
  // its entity's first physical tag, from $Entities).
  std::optional<std::int64_t> physical_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> entity_physical_;
};

}  // namespace

MeshData read_gmsh(const std::string& source, std::string_view text) {
  return GmshReader(source, text).read();
}

}  // namespace rift::io
