#include "rift/output/obj_writer.hpp"

#include "rift/output/file_sink.hpp"

namespace rift {

void format_obj(const FrameMesh& frame, std::string& out) {
  out.clear();
  out += "# rift frame: ";
  append_int(out, static_cast<std::int64_t>(frame.point_count()));
  out += " vertices, ";
  append_int(out, static_cast<std::int64_t>(frame.face_count()));
  out += " faces\n";
  for (const Vec3& p : frame.points) {
    out += "v ";
    append_real(out, p.x());
    out += ' ';
    append_real(out, p.y());
    out += ' ';
    append_real(out, p.z());
    out += '\n';
  }
  int group = -1;
  for (std::size_t f = 0; f < frame.face_count(); ++f) {
    const int torn = frame.face_torn[f] ? 1 : 0;
    if (torn != group) {
      out += torn ? "g torn\n" : "g intact\n";
      group = torn;
    }
    out += 'f';
    for (std::uint32_t k = frame.face_offsets[f]; k < frame.face_offsets[f + 1]; ++k) {
      out += ' ';
      append_int(out, static_cast<std::int64_t>(frame.face_vertices[k]) + 1);
    }
    out += '\n';
  }
}

void ObjWriter::write(const FrameMesh& frame, const std::filesystem::path& path) {
  format_obj(frame, text_);
  write_file_atomically(path, text_);
}

}  // namespace rift
