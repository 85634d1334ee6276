#include "rift/output/vtu_writer.hpp"

#include <span>

#include "rift/output/file_sink.hpp"

namespace rift {

namespace {

// Values per line in the ASCII arrays: short lines keep the files diffable.
constexpr std::size_t kValuesPerLine = 12;

void open_array(std::string& out, const char* type, std::string_view name, int components) {
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
  out += " format=\"ascii\">\n";
}

void close_array(std::string& out) {
  out += "        </DataArray>\n";
}

template <class T, class Append>
void append_values(std::string& out, std::span<const T> values, std::size_t per_line,
                   Append&& append) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    out += (k % per_line == 0) ? "          " : " ";
    append(out, values[k]);
    if (k % per_line == per_line - 1 || k + 1 == values.size()) out += '\n';
  }
}

void real_array(std::string& out, std::string_view name, int components,
                std::span<const Real> values) {
  open_array(out, "Float64", name, components);
  const std::size_t per_line = components == 3 ? 9 : kValuesPerLine;
  append_values(out, values, per_line, [](std::string& o, Real v) { append_real(o, v); });
  close_array(out);
}

void int_array(std::string& out, const char* type, std::string_view name,
               std::span<const std::int64_t> values) {
  open_array(out, type, name, 1);
  append_values(out, values, kValuesPerLine,
                [](std::string& o, std::int64_t v) { append_int(o, v); });
  close_array(out);
}

void byte_array(std::string& out, std::string_view name, std::span<const std::uint8_t> values) {
  open_array(out, "UInt8", name, 1);
  append_values(out, values, 2 * kValuesPerLine,
                [](std::string& o, std::uint8_t v) { append_int(o, v); });
  close_array(out);
}

void frame_arrays(std::string& out, const std::vector<FrameArray>& arrays) {
  for (const FrameArray& a : arrays) {
    if (a.integral) {
      int_array(out, "Int64", a.name, a.ints);
    } else {
      real_array(out, a.name, a.components, a.reals);
    }
  }
}

const FrameArray* first_vector(const std::vector<FrameArray>& arrays) {
  for (const FrameArray& a : arrays) {
    if (a.components == 3) return &a;
  }
  return nullptr;
}

}  // namespace

void format_vtu(const FrameMesh& frame, double time, std::string& out) {
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
  frame_arrays(out, frame.point_data);
  out += "      </PointData>\n";

  out += "      <CellData Scalars=\"torn\">\n";
  int_array(out, "Int64", "element_id", frame.element_ids);
  byte_array(out, "torn", frame.torn);
  frame_arrays(out, frame.cell_data);
  out += "      </CellData>\n";

  out += "      <Points>\n";
  open_array(out, "Float64", "Points", 3);
  for (std::size_t k = 0; k < frame.points.size(); ++k) {
    const Vec3& p = frame.points[k];
    out += "          ";
    append_real(out, p.x());
    out += ' ';
    append_real(out, p.y());
    out += ' ';
    append_real(out, p.z());
    out += '\n';
  }
  close_array(out);
  out += "      </Points>\n";

  out += "      <Cells>\n";
  int_array(out, "Int64", "connectivity", frame.connectivity);
  int_array(out, "Int64", "offsets", frame.offsets);
  open_array(out, "UInt8", "types", 1);
  append_values(out, std::span<const VtkCell>(frame.cell_types), 2 * kValuesPerLine,
                [](std::string& o, VtkCell t) { append_int(o, static_cast<std::int64_t>(t)); });
  close_array(out);
  if (!frame.polyhedron_faces.empty()) {
    int_array(out, "Int64", "faces", frame.polyhedron_faces);
    int_array(out, "Int64", "faceoffsets", frame.polyhedron_face_offsets);
  }
  out += "      </Cells>\n";
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
}

void VtuWriter::write(const FrameMesh& frame, const std::filesystem::path& path, double time) {
  format_vtu(frame, time, text_);
  write_file_atomically(path, text_);
}

}  // namespace rift
