#include "rift/output/file_sink.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <system_error>

#include "rift/output/output_error.hpp"

namespace rift {

void ensure_directory(const std::filesystem::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw OutputError("create folder", dir, ec);
  if (!std::filesystem::is_directory(dir, ec)) {
    throw OutputError("create folder", dir, std::make_error_code(std::errc::not_a_directory));
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view data) {
  std::filesystem::path temp = path;
  temp += ".tmp";
  errno = 0;
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file) throw OutputError("create", temp, last_os_error());
  errno = 0;
  const bool written =
      std::fwrite(data.data(), 1, data.size(), file) == data.size() && std::fflush(file) == 0;
  std::error_code ec = written ? std::error_code() : last_os_error();
  errno = 0;
  if (std::fclose(file) != 0 && !ec) ec = last_os_error();
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw OutputError("write", path, ec);
  }
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw OutputError("replace", path, ec);
  }
}

std::string frame_file_name(std::string_view prefix, std::size_t index, std::string_view extension,
                            int digits) {
  std::string number = std::to_string(index);
  std::string name(prefix);
  if (static_cast<int>(number.size()) < digits) {
    name.append(static_cast<std::size_t>(digits) - number.size(), '0');
  }
  name += number;
  name += '.';
  name += extension;
  return name;
}

void append_real(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_int(std::string& out, std::int64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_xml_escaped(std::string& out, std::string_view text) {
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
}

}  // namespace rift
