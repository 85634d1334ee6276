#include "rift/output/csv_writer.hpp"

#include <cerrno>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include "rift/output/file_sink.hpp"
#include "rift/output/output_error.hpp"

namespace rift {

namespace {

void append_field(std::string& out, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    out += text;
    return;
  }
  out += '"';
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

}  // namespace

CsvWriter::CsvWriter(std::filesystem::path path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("a CSV file needs at least one column");
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    for (std::size_t m = 0; m < k; ++m) {
      if (columns_[m] == columns_[k]) {
        throw std::invalid_argument("CSV column '" + columns_[k] + "' is given twice");
      }
    }
  }
  errno = 0;
  file_.reset(std::fopen(path_.c_str(), "wb"));
  if (!file_) throw OutputError("create", path_, last_os_error());
  line_.clear();
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    if (k) line_ += ',';
    append_field(line_, columns_[k]);
  }
  emit();
}

std::size_t CsvWriter::column_index(std::string_view name) const {
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    if (columns_[k] == name) return k;
  }
  return columns_.size();
}

void CsvWriter::write_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument("CSV row has " + std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  }
  line_.clear();
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) line_ += ',';
    const double v = values[k];
    if (std::isfinite(v) && v == std::trunc(v) && std::abs(v) < 9.0e15) {
      append_int(line_, static_cast<std::int64_t>(v));
    } else {
      append_real(line_, v);
    }
  }
  emit();
  ++rows_;
}

void CsvWriter::emit() {
  line_ += '\n';
  errno = 0;
  if (std::fwrite(line_.data(), 1, line_.size(), file_.get()) != line_.size() ||
      std::fflush(file_.get()) != 0) {
    throw OutputError("write", path_, last_os_error());
  }
}

}  // namespace rift
