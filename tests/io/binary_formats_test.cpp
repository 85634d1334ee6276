// Binary VTU (inline base64, appended raw or base64, zlib or not, UInt32 or
// UInt64 headers, either byte order) and binary Gmsh 2.2 and 4.1 (either byte
// order). The files are written here by test writers from the shapes of
// shapes.hpp, and each must read to exactly the mesh its ASCII twin reads to.
// Then rift's own VTU writer: appended binary and ASCII both read back exactly.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "io_test_support.hpp"
#include "rift/io/readers.hpp"
#include "rift/io/vtk_binary.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/output/frame_mesh.hpp"
#include "rift/output/vtu_writer.hpp"
#include "shapes.hpp"

namespace rift::test {
namespace {

// ---- a byte writer in either order ----

struct Bytes {
  bool big_endian = false;
  std::vector<std::uint8_t> data;

  void put(std::uint64_t bits, int size) {
    for (int k = 0; k < size; ++k) {
      const int shift = 8 * (big_endian ? size - 1 - k : k);
      data.push_back(static_cast<std::uint8_t>(bits >> shift));
    }
  }
  void real64(double v) { put(std::bit_cast<std::uint64_t>(v), 8); }
  void real32(float v) { put(std::bit_cast<std::uint32_t>(v), 4); }
  void int32(std::int64_t v) { put(static_cast<std::uint32_t>(v), 4); }
  void int64(std::int64_t v) { put(static_cast<std::uint64_t>(v), 8); }
  std::string str() const { return std::string(data.begin(), data.end()); }
};

// ---- VTU ----

enum class VtuForm { kInline, kAppendedRaw, kAppendedBase64 };

struct VtuOptions {
  VtuForm form = VtuForm::kInline;
  bool zlib = false;
  int header_bytes = 4;
  bool big_endian = false;
  bool float32 = false;  // Float32 points and Int32 connectivity/offsets
};

std::string describe(const VtuOptions& o) {
  const char* forms[] = {"inline", "appended-raw", "appended-base64"};
  return std::string(forms[static_cast<int>(o.form)]) + (o.zlib ? " zlib" : "") + " UInt" +
         std::to_string(8 * o.header_bytes) + (o.big_endian ? " big-endian" : "") +
         (o.float32 ? " 32-bit values" : "");
}

// One array's stored bytes: [header][data], or the zlib block layout.
std::vector<std::uint8_t> encode_array(const Bytes& values, const VtuOptions& o) {
  if (o.zlib) {
    std::vector<std::uint8_t> blocks = io::vtk_zlib_blocks(values.data.data(), values.data.size(),
                                                           o.header_bytes, /*block_size=*/64);
    if (o.big_endian) {
      // The writer gives little-endian header integers: turn them around.
      const std::size_t count = blocks[0] + 3u;  // shapes have fewer than 256 blocks
      for (std::size_t k = 0; k < count; ++k) {
        auto* h = blocks.data() + k * static_cast<std::size_t>(o.header_bytes);
        std::reverse(h, h + o.header_bytes);
      }
    }
    return blocks;
  }
  Bytes out{o.big_endian, {}};
  out.put(values.data.size(), o.header_bytes);
  out.data.insert(out.data.end(), values.data.begin(), values.data.end());
  return out.data;
}

// In base64, VTK encodes a compressed array's header apart from its blocks.
std::string base64_array(const std::vector<std::uint8_t>& stored, const VtuOptions& o) {
  std::string text;
  if (!o.zlib) {
    io::append_base64(text, stored.data(), stored.size());
    return text;
  }
  Bytes probe{o.big_endian, {}};
  const std::size_t blocks =
      o.big_endian ? stored[static_cast<std::size_t>(o.header_bytes) - 1] : stored[0];
  const std::size_t header = (3 + blocks) * static_cast<std::size_t>(o.header_bytes);
  io::append_base64(text, stored.data(), header);
  io::append_base64(text, stored.data() + header, stored.size() - header);
  return text;
}

std::string to_binary_vtu(const Shape& s, const VtuOptions& o) {
  Bytes points{o.big_endian, {}}, conn{o.big_endian, {}}, offsets{o.big_endian, {}},
      types{o.big_endian, {}};
  for (const Vec3& p : s.points) {
    for (int c = 0; c < 3; ++c)
      o.float32 ? points.real32(static_cast<float>(p[c])) : points.real64(p[c]);
  }
  std::int64_t end = 0;
  for (const ShapeElement& e : s.elements) {
    for (std::uint32_t v : e.v)
      o.float32 ? conn.int32(v) : conn.int64(v);
    end += static_cast<std::int64_t>(e.v.size());
    o.float32 ? offsets.int32(end) : offsets.int64(end);
    types.put(static_cast<std::uint64_t>(vtk_type(e)), 1);
  }
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"";
  xml += std::string(" byte_order=\"") + (o.big_endian ? "BigEndian" : "LittleEndian") + "\"";
  xml += " header_type=\"UInt" + std::to_string(8 * o.header_bytes) + "\"";
  if (o.zlib) xml += " compressor=\"vtkZLibDataCompressor\"";
  xml += ">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" + std::to_string(s.points.size()) +
         "\" NumberOfCells=\"" + std::to_string(s.elements.size()) + "\">\n";
  std::string appended;
  const char* real_type = o.float32 ? "Float32" : "Float64";
  const char* int_type = o.float32 ? "Int32" : "Int64";
  auto array = [&](const char* type, const char* name, int components, const Bytes& values) {
    const std::vector<std::uint8_t> stored = encode_array(values, o);
    std::string tag = std::string("        <DataArray type=\"") + type + "\"";
    if (name) tag += std::string(" Name=\"") + name + "\"";
    if (components != 1) tag += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    if (o.form == VtuForm::kInline) {
      return tag + " format=\"binary\">\n          " + base64_array(stored, o) +
             "\n        </DataArray>\n";
    }
    tag += " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
    if (o.form == VtuForm::kAppendedRaw) {
      appended.append(stored.begin(), stored.end());
    } else {
      appended += base64_array(stored, o);
    }
    return tag;
  };
  xml += "      <Points>\n" + array(real_type, nullptr, 3, points) + "      </Points>\n";
  xml += "      <Cells>\n" + array(int_type, "connectivity", 1, conn) +
         array(int_type, "offsets", 1, offsets) + array("UInt8", "types", 1, types) +
         "      </Cells>\n";
  xml += "    </Piece>\n  </UnstructuredGrid>\n";
  if (o.form != VtuForm::kInline) {
    xml += std::string("  <AppendedData encoding=\"") +
           (o.form == VtuForm::kAppendedRaw ? "raw" : "base64") + "\">\n   _" + appended +
           "\n  </AppendedData>\n";
  }
  xml += "</VTKFile>\n";
  return xml;
}

void expect_same_mesh(const MeshData& got, const MeshData& want, bool float32) {
  EXPECT_EQ(got.dimension, want.dimension);
  ASSERT_EQ(got.points.size(), want.points.size());
  for (std::size_t k = 0; k < got.points.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      const double expected =
          float32 ? static_cast<double>(static_cast<float>(want.points[k][c])) : want.points[k][c];
      EXPECT_EQ(got.points[k][c], expected) << "point " << k;
    }
  }
  EXPECT_EQ(got.element_vertices, want.element_vertices);
  ASSERT_EQ(got.elements.size(), want.elements.size());
  for (std::size_t k = 0; k < got.elements.size(); ++k)
    EXPECT_EQ(got.elements[k].type, want.elements[k].type) << "element " << k;
}

TEST(BinaryVtu, EveryEncodingReadsLikeTheAsciiFile) {
  int files = 0;
  for (const Shape& s : shapes()) {
    const MeshData ascii = io::read_vtu(s.name + ".vtu", to_vtu(s));
    for (VtuForm form : {VtuForm::kInline, VtuForm::kAppendedRaw, VtuForm::kAppendedBase64}) {
      for (bool zlib : {false, true}) {
        for (int header : {4, 8}) {
          for (bool big : {false, true}) {
            for (bool f32 : {false, true}) {
              const VtuOptions o{form, zlib, header, big, f32};
              SCOPED_TRACE(s.name + " " + describe(o));
              const std::string text = to_binary_vtu(s, o);
              MeshData got;
              ASSERT_NO_THROW(got = io::read_vtu(s.name + ".vtu", text));
              expect_same_mesh(got, ascii, f32);
              const GMap map = assemble_gmap(got);
              EXPECT_EQ(counts_of(map), s.expected);
              ++files;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(files, 100);
}

// A raw appended file holds every byte value, '<' and '&' included: the XML
// parser must never see it.
TEST(BinaryVtu, RawAppendedBytesThatLookLikeXmlAreData) {
  Shape s = shapes()[0];
  // 0x3C is '<' and 0x26 is '&': a coordinate (about 11.07) made of them.
  s.points[1] = Vec3(std::bit_cast<double>(std::uint64_t{0x40263C3C3C3C3C26}), 0, 0);
  const MeshData got =
      io::read_vtu("lt.vtu", to_binary_vtu(s, {VtuForm::kAppendedRaw, false, 4, false, false}));
  EXPECT_EQ(got.points[1].x(), std::bit_cast<double>(std::uint64_t{0x40263C3C3C3C3C26}));
}

std::string vtu_error(const std::string& text) {
  try {
    io::read_vtu("bad.vtu", text);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BinaryVtu, DamagedBinaryDataIsALocatedError) {
  const Shape s = shapes()[0];
  // Inline base64 with a character outside the alphabet.
  std::string text = to_binary_vtu(s, {VtuForm::kInline, false, 4, false, false});
  text.replace(text.find("format=\"binary\">\n          ") + 27, 1, "*");
  EXPECT_NE(vtu_error(text).find(
                "bad.vtu:6: error: DataArray Points (binary): character '*' is not base64"),
            std::string::npos)
      << vtu_error(text);

  // A header announcing 2^32 - 1 bytes: refused, nothing allocated.
  text = to_binary_vtu(s, {VtuForm::kAppendedRaw, false, 4, false, false});
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
  text.replace(data, 4, std::string("\xff\xff\xff\xff", 4));
  EXPECT_NE(vtu_error(text).find("the header announces 4294967295 bytes, but only"),
            std::string::npos)
      << vtu_error(text);

  // zlib: a lying block count, then a corrupted block.
  text = to_binary_vtu(s, {VtuForm::kAppendedRaw, true, 8, false, false});
  const std::size_t zdata = text.find('_', text.find("<AppendedData")) + 1;
  std::string lying = text;
  lying.replace(zdata, 8, std::string("\xff\xff\xff\xff\xff\xff\x00\x00", 8));
  EXPECT_NE(vtu_error(lying).find("blocks, more than the data can hold"), std::string::npos)
      << vtu_error(lying);
  std::string corrupt = text;
  const std::size_t blocks_at = zdata + 8 * (3 + static_cast<unsigned char>(text[zdata])) + 2;
  corrupt[blocks_at] = static_cast<char>(corrupt[blocks_at] ^ 0x55);
  EXPECT_NE(vtu_error(corrupt).find("does not inflate to"), std::string::npos)
      << vtu_error(corrupt);

  // An offset past the appended data.
  text = to_binary_vtu(s, {VtuForm::kAppendedRaw, false, 4, false, false});
  text.replace(text.find("offset=\"0\""), 10, "offset=\"99999\"");
  EXPECT_NE(vtu_error(text).find("has offset 99999, outside the appended data"), std::string::npos)
      << vtu_error(text);

  // Floats where integers are expected.
  text = to_binary_vtu(s, {VtuForm::kInline, false, 4, false, false});
  text.replace(text.find("type=\"Int64\" Name=\"connectivity\""), 12, "type=\"Float64\"");
  EXPECT_NE(vtu_error(text).find("DataArray connectivity has type Float64, expected an integer"),
            std::string::npos)
      << vtu_error(text);
}

// ---- Gmsh ----

std::string to_gmsh_binary(const Shape& s, int version, bool big_endian) {
  Bytes b{big_endian, {}};
  auto text = [&](const std::string& t) { b.data.insert(b.data.end(), t.begin(), t.end()); };
  text(version == 2 ? "$MeshFormat\n2.2 1 8\n" : "$MeshFormat\n4.1 1 8\n");
  b.int32(1);
  text("\n$EndMeshFormat\n");
  if (version == 2) {
    text("$PhysicalNames\n1\n2 1 \"skin\"\n$EndPhysicalNames\n");
    text("$Nodes\n" + std::to_string(s.points.size()) + "\n");
    for (std::size_t i = s.points.size(); i-- > 0;) {
      b.int32(gmsh_tag(i));
      for (int c = 0; c < 3; ++c)
        b.real64(s.points[i][c]);
    }
    text("\n$EndNodes\n$Elements\n" + std::to_string(s.elements.size() + 1) + "\n");
    // A line (ignored), then one block per element (type, 1 follows, 2 tags).
    b.int32(1), b.int32(1), b.int32(2);
    b.int32(100), b.int32(0), b.int32(0), b.int32(gmsh_tag(s.elements[0].v[0])),
        b.int32(gmsh_tag(s.elements[0].v[1]));
    int tag = 1;
    for (const ShapeElement& e : s.elements) {
      b.int32(gmsh_type(e)), b.int32(1), b.int32(2);
      b.int32(tag++), b.int32(7), b.int32(1);  // physical group 7, elementary 1
      for (std::uint32_t i : gmsh_order(e))
        b.int32(gmsh_tag(i));
    }
    text("\n$EndElements\n");
    return b.str();
  }
  // 4.1: a binary $Entities section, then one node block, then a line block
  // and one block per element. Entities: a point, the line's curve (physical
  // group 3, bounded by the point and an oriented -1), and the elements'
  // entity of the shape's dimension (groups 5 and 6: the first is theirs).
  text("$Entities\n");
  b.int64(1), b.int64(1), b.int64(s.dimension == 2 ? 1 : 0), b.int64(s.dimension == 3 ? 1 : 0);
  b.int32(1), b.real64(0), b.real64(0), b.real64(0), b.int64(0);
  b.int32(1);
  for (int c = 0; c < 6; ++c)
    b.real64(c < 3 ? 0 : 1);
  b.int64(1), b.int32(3), b.int64(2), b.int32(1), b.int32(-1);
  b.int32(1);
  for (int c = 0; c < 6; ++c)
    b.real64(c < 3 ? 0 : 1);
  b.int64(2), b.int32(5), b.int32(6), b.int64(0);
  text("\n$EndEntities\n$Nodes\n");
  b.int64(1), b.int64(static_cast<std::int64_t>(s.points.size())), b.int64(1),
      b.int64(gmsh_tag(s.points.size()));
  b.int32(s.dimension), b.int32(1), b.int32(0), b.int64(static_cast<std::int64_t>(s.points.size()));
  for (std::size_t i = s.points.size(); i-- > 0;)
    b.int64(gmsh_tag(i));
  for (std::size_t i = s.points.size(); i-- > 0;) {
    for (int c = 0; c < 3; ++c)
      b.real64(s.points[i][c]);
  }
  text("\n$EndNodes\n$Elements\n");
  const auto n = static_cast<std::int64_t>(s.elements.size() + 1);
  b.int64(n), b.int64(n), b.int64(1), b.int64(n);
  b.int32(1), b.int32(1), b.int32(1), b.int64(1);
  b.int64(100), b.int64(gmsh_tag(s.elements[0].v[0])), b.int64(gmsh_tag(s.elements[0].v[1]));
  int tag = 1;
  for (const ShapeElement& e : s.elements) {
    b.int32(s.dimension), b.int32(1), b.int32(gmsh_type(e)), b.int64(1);
    b.int64(tag++);
    for (std::uint32_t i : gmsh_order(e))
      b.int64(gmsh_tag(i));
  }
  text("\n$EndElements\n");
  return b.str();
}

TEST(BinaryGmsh, Version22And41ReadLikeTheAsciiFiles) {
  for (const Shape& s : shapes()) {
    const MeshData ascii2 = io::read_gmsh(s.name + ".msh", to_gmsh12(s, 2));
    const MeshData ascii4 = io::read_gmsh(s.name + ".msh", to_gmsh41(s));
    for (bool big : {false, true}) {
      SCOPED_TRACE(s.name + (big ? " big-endian" : " little-endian"));
      MeshData got2, got4;
      ASSERT_NO_THROW(got2 = io::read_gmsh(s.name + ".msh", to_gmsh_binary(s, 2, big)));
      expect_same_mesh(got2, ascii2, false);
      ASSERT_NO_THROW(got4 = io::read_gmsh(s.name + ".msh", to_gmsh_binary(s, 4, big)));
      expect_same_mesh(got4, ascii4, false);
      EXPECT_EQ(counts_of(assemble_gmap(got4)), s.expected);
      // Physical groups: v2's first element tag, v4.1's entity's first tag.
      EXPECT_EQ(got2.element_tags, std::vector<std::int64_t>(s.elements.size(), 7));
      EXPECT_EQ(got4.element_tags, std::vector<std::int64_t>(s.elements.size(), 5));
    }
  }
}

std::string gmsh_error(const std::string& text) {
  try {
    io::read_gmsh("bad.msh", text);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BinaryGmsh, DamagedBinaryDataIsALocatedError) {
  const Shape s = shapes()[0];
  std::string text = to_gmsh_binary(s, 2, false);
  // The endianness marker.
  std::string marker = text;
  marker[text.find("8\n") + 2] = 7;
  EXPECT_NE(gmsh_error(marker).find("bad.msh:3: error: the binary marker after the format line "
                                    "is not the integer 1"),
            std::string::npos)
      << gmsh_error(marker);
  // Cut in the middle of the nodes: the count is checked against what is left.
  const std::string cut = text.substr(0, text.find("$Nodes") + 20);
  EXPECT_NE(gmsh_error(cut).find("section $Nodes announces 4 nodes, more than the rest of the "
                                 "file can hold"),
            std::string::npos)
      << gmsh_error(cut);
  // Cut in an element block's header.
  const std::size_t elements = text.find('\n', text.find("$Elements\n") + 10) + 1;
  const std::string cut_block = text.substr(0, elements + 5);
  EXPECT_NE(gmsh_error(cut_block).find("unexpected end of file in binary data at byte " +
                                       std::to_string(elements + 4) +
                                       ", expected the number of elements in the block"),
            std::string::npos)
      << gmsh_error(cut_block);
  // A node count no file of this size can hold: refused before reserving.
  std::string many = text;
  const std::size_t count = many.find("$Nodes\n") + 7;
  many.replace(count, many.find('\n', count) - count, "2000000000");
  EXPECT_NE(gmsh_error(many).find("announces 2000000000 nodes, more than the rest of the file can "
                                  "hold"),
            std::string::npos)
      << gmsh_error(many);
  // 4.1: an element referring to a node that does not exist.
  std::string v4 = to_gmsh_binary(s, 4, false);
  const std::size_t last = v4.rfind("\n$EndElements") - 8;
  v4.replace(last, 8, std::string("\x39\x05\0\0\0\0\0\0", 8));
  EXPECT_NE(gmsh_error(v4).find("refers to node 1337, which is not defined"), std::string::npos)
      << gmsh_error(v4);
  // 4.1: $Entities announcing more points than the file holds (the count is
  // the first size_t after the header line), then a physical-tag count.
  std::string entities = to_gmsh_binary(s, 4, false);
  const std::size_t points = entities.find("$Entities\n") + 10;
  entities.replace(points, 8, std::string("\0\0\0\x40\0\0\0\0", 8));
  EXPECT_NE(gmsh_error(entities).find("section $Entities announces 1073741824 entities, more than "
                                      "the rest of the file can hold"),
            std::string::npos)
      << gmsh_error(entities);
  entities = to_gmsh_binary(s, 4, false);
  // The point's physical-tag count: after its tag (4 bytes) and x, y, z.
  const std::size_t physicals = entities.find("$Entities\n") + 10 + 32 + 4 + 24;
  entities.replace(physicals, 8, std::string("\xff\xff\xff\0\0\0\0\0", 8));
  EXPECT_NE(gmsh_error(entities).find("section $Entities announces 16777215 physical tags, more "
                                      "than the rest of the file can hold"),
            std::string::npos)
      << gmsh_error(entities);
}

// ---- rift's own VTU writer ----

TEST(VtuWriterRoundTrip, AppendedBinaryAndAsciiReadBackExactly) {
  for (const char* spec : {"grid:quad:6x4", "block:tet:2x3x2", "block:hex:2x2x3"}) {
    SCOPED_TRACE(spec);
    MeshData mesh = make_generated_mesh(spec);
    // Reals that text must spell exactly: thirds and tiny offsets.
    for (std::size_t k = 0; k < mesh.points.size(); ++k)
      mesh.points[k] += Vec3(1.0 / 3, 1e-17 * static_cast<double>(k), -2.0 / 7);
    const FrameMesh frame = extract_frame_mesh(assemble_gmap(mesh));
    std::string binary, ascii, scratch;
    format_vtu(frame, 0.5, binary, VtuEncoding::kAppendedBinary, &scratch);
    format_vtu(frame, 0.5, ascii, VtuEncoding::kAscii);
    EXPECT_NE(binary.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    EXPECT_EQ(ascii.find("AppendedData"), std::string::npos);
    EXPECT_LT(binary.size(), ascii.size());
    const MeshData from_binary = io::read_vtu("binary.vtu", binary);
    const MeshData from_ascii = io::read_vtu("ascii.vtu", ascii);
    ASSERT_EQ(from_binary.points.size(), frame.points.size());
    for (std::size_t k = 0; k < frame.points.size(); ++k)
      EXPECT_EQ(from_binary.points[k], frame.points[k]) << k;
    expect_same_mesh(from_ascii, from_binary, false);
    std::vector<std::uint32_t> connectivity(frame.connectivity.begin(), frame.connectivity.end());
    EXPECT_EQ(from_binary.element_vertices, connectivity);
  }
}

}  // namespace
}  // namespace rift::test
