#include "emit/writer.hpp"

namespace rift::emit {

void Writer::line(std::string_view text) {
  if (!text.empty()) out_.append(static_cast<std::size_t>(indent_) * 2, ' ');
  out_ += text;
  out_ += '\n';
  ++lines_;
}

void Writer::open(std::string_view text) {
  line(text);
  ++indent_;
}

void Writer::close(std::string_view text) {
  --indent_;
  line(text);
}

void Writer::middle(std::string_view text) {
  --indent_;
  line(text);
  ++indent_;
}

void Writer::from_source(const diag::Location& loc) {
  if (!loc.valid() || !line_directives_) return;
  line("#line " + std::to_string(loc.begin.line) + " " + quote(sources_->file(loc.file).path));
}

void Writer::resume() {
  // The directive names the number of the line that follows it.
  if (!line_directives_) return;
  line("#line " + std::to_string(lines_ + 2) + " " + quote(output_name_));
}

std::string quote(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string Writer::where(const diag::Location& loc) const {
  if (!loc.valid()) return "";
  return sources_->file(loc.file).path + ":" + std::to_string(loc.begin.line) + ":" +
         std::to_string(loc.begin.column) + ": ";
}

}  // namespace rift::emit
