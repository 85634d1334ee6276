#include "rift/output/vtu_writer.hpp"

#include <algorithm>
#include <bit>
#include <span>

#include "rift/output/file_sink.hpp"

namespace rift {

namespace {

// Values per line in the ASCII arrays: short lines keep the files diffable.
constexpr std::size_t kValuesPerLine = 12;

// Where the values of the arrays go: inline text, or the appended block with
// an offset in the DataArray tag.
struct ArrayOut {
  std::string& out;
  std::string* appended;  // null: ASCII

  void open(const char* type, std::string_view name, int components) {
    out += "        <DataArray type=\"";
    out += type;
    out += '"';
    if (!name.empty()) {
      out += " Name=\"";
      append_xml_escaped(out, name);
      out += '"';
    }
    if (components != 1) {
      out += " NumberOfComponents=\"";
      append_int(out, components);
      out += '"';
    }
    if (appended) {
      out += " format=\"appended\" offset=\"";
      append_int(out, static_cast<std::int64_t>(appended->size()));
      out += "\"/>\n";
    } else {
      out += " format=\"ascii\">\n";
    }
  }

  void close() {
    if (!appended) out += "        </DataArray>\n";
  }

  // Little-endian whatever the host: the file says byte_order="LittleEndian".
  void append_le(std::uint64_t bits, int bytes) {
    for (int k = 0; k < bytes; ++k)
      appended->push_back(static_cast<char>((bits >> (8 * k)) & 0xff));
  }

  // One array: text with `per_line` values a line, or [UInt64 byte count][values].
  template <class T, class Text, class Bits>
  void values(std::span<const T> values, int bytes, std::size_t per_line, Text&& text,
              Bits&& bits) {
    if (appended) {
      append_le(static_cast<std::uint64_t>(values.size()) * static_cast<std::uint64_t>(bytes), 8);
      for (const T& v : values)
        append_le(bits(v), bytes);
      return;
    }
    for (std::size_t k = 0; k < values.size(); ++k) {
      out += (k % per_line == 0) ? "          " : " ";
      text(out, values[k]);
      if (k % per_line == per_line - 1 || k + 1 == values.size()) out += '\n';
    }
  }

  void reals(std::string_view name, int components, std::span<const Real> v) {
    open("Float64", name, components);
    values(
        v, 8, components == 3 ? 9 : kValuesPerLine,
        [](std::string& o, Real x) { append_real(o, x); },
        [](Real x) { return std::bit_cast<std::uint64_t>(static_cast<double>(x)); });
    close();
  }

  // In binary, ids that fit (all of them below 2^31 points or elements) are
  // stored as Int32: half the bytes, and what ParaView writes for such meshes.
  void ints(std::string_view name, std::span<const std::int64_t> v) {
    const bool narrow = appended && std::all_of(v.begin(), v.end(), [](std::int64_t x) {
                          return x >= INT32_MIN && x <= INT32_MAX;
                        });
    open(narrow ? "Int32" : "Int64", name, 1);
    values(
        v, narrow ? 4 : 8, kValuesPerLine, [](std::string& o, std::int64_t x) { append_int(o, x); },
        [](std::int64_t x) { return static_cast<std::uint64_t>(x); });
    close();
  }

  void bytes(std::string_view name, std::span<const std::uint8_t> v) {
    open("UInt8", name, 1);
    values(
        v, 1, 2 * kValuesPerLine, [](std::string& o, std::uint8_t x) { append_int(o, x); },
        [](std::uint8_t x) { return std::uint64_t{x}; });
    close();
  }

  void frame_arrays(const std::vector<FrameArray>& arrays) {
    for (const FrameArray& a : arrays) {
      if (a.integral) {
        ints(a.name, a.ints);
      } else {
        reals(a.name, a.components, a.reals);
      }
    }
  }
};

const FrameArray* first_vector(const std::vector<FrameArray>& arrays) {
  for (const FrameArray& a : arrays) {
    if (a.components == 3) return &a;
  }
  return nullptr;
}

}  // namespace

void format_vtu(const FrameMesh& frame, double time, std::string& out, VtuEncoding encoding,
                std::string* scratch) {
  std::string local;
  std::string& appended = scratch ? *scratch : local;
  appended.clear();
  ArrayOut arrays{out, encoding == VtuEncoding::kAppendedBinary ? &appended : nullptr};
  out.clear();
  out += "<?xml version=\"1.0\"?>\n";
  out +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  out += "    <FieldData>\n";
  out +=
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">";
  append_real(out, time);
  out += "</DataArray>\n";
  out += "    </FieldData>\n";
  out += "    <Piece NumberOfPoints=\"";
  append_int(out, static_cast<std::int64_t>(frame.point_count()));
  out += "\" NumberOfCells=\"";
  append_int(out, static_cast<std::int64_t>(frame.element_count()));
  out += "\">\n";

  out += "      <PointData";
  if (const FrameArray* v = first_vector(frame.point_data)) {
    out += " Vectors=\"";
    append_xml_escaped(out, v->name);
    out += '"';
  }
  out += ">\n";
  arrays.frame_arrays(frame.point_data);
  out += "      </PointData>\n";

  out += "      <CellData Scalars=\"torn\">\n";
  arrays.ints("element_id", frame.element_ids);
  arrays.bytes("torn", frame.torn);
  arrays.frame_arrays(frame.cell_data);
  out += "      </CellData>\n";

  out += "      <Points>\n";
  static_assert(sizeof(Vec3) == 3 * sizeof(Real), "points are read as a flat array of reals");
  arrays.reals("Points", 3,
               std::span<const Real>(frame.points.empty() ? nullptr : frame.points[0].data(),
                                     3 * frame.points.size()));
  out += "      </Points>\n";

  out += "      <Cells>\n";
  arrays.ints("connectivity", frame.connectivity);
  arrays.ints("offsets", frame.offsets);
  std::vector<std::uint8_t> types(frame.cell_types.size());
  std::transform(frame.cell_types.begin(), frame.cell_types.end(), types.begin(),
                 [](VtkCell t) { return static_cast<std::uint8_t>(t); });
  arrays.bytes("types", types);
  if (!frame.polyhedron_faces.empty()) {
    arrays.ints("faces", frame.polyhedron_faces);
    arrays.ints("faceoffsets", frame.polyhedron_face_offsets);
  }
  out += "      </Cells>\n";
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  if (encoding == VtuEncoding::kAppendedBinary) {
    // The raw bytes follow the '_' up to the closing tag; readers find each
    // array at its offset, counted from the byte after '_'.
    out += "  <AppendedData encoding=\"raw\">\n   _";
    out += appended;
    out += "\n  </AppendedData>\n";
  }
  out += "</VTKFile>\n";
}

void VtuWriter::write(const FrameMesh& frame, const std::filesystem::path& path, double time) {
  format_vtu(frame, time, text_, encoding_, &appended_);
  write_file_atomically(path, text_);
}

}  // namespace rift
