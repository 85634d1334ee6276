#include "rift/output/pvd_writer.hpp"

#include "rift/output/file_sink.hpp"

namespace rift {

PvdWriter::PvdWriter(std::filesystem::path path) : path_(std::move(path)) {
  rewrite();
}

void PvdWriter::add(double time, std::string_view file) {
  entries_ += "    <DataSet timestep=\"";
  append_real(entries_, time);
  entries_ += "\" group=\"\" part=\"0\" file=\"";
  append_xml_escaped(entries_, file);
  entries_ += "\"/>\n";
  ++count_;
  rewrite();
}

void PvdWriter::rewrite() {
  text_.clear();
  text_ += "<?xml version=\"1.0\"?>\n";
  text_ += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  text_ += "  <Collection>\n";
  text_ += entries_;
  text_ += "  </Collection>\n";
  text_ += "</VTKFile>\n";
  write_file_atomically(path_, text_);
}

}  // namespace rift
