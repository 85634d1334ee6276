// Statistics per frame as CSV: a header row with the caller's column names,
// then one row per frame, flushed as it is written so that a crash keeps
// every finished row.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rift {

class CsvWriter {
 public:
  /// Creates (or truncates) `path` and writes the header. Column names with
  /// a comma, a quote or a line break are quoted (RFC 4180). Throws
  /// OutputError, or std::invalid_argument for no column or a repeated name.
  CsvWriter(std::filesystem::path path, std::vector<std::string> columns);

  /// Appends one row, one value per column in header order, and flushes it.
  /// Integral values print without a decimal point; reals print exactly.
  /// Throws std::invalid_argument on a wrong count, OutputError on I/O failure.
  void write_row(std::span<const double> values);
  void write_row(std::initializer_list<double> values) {
    write_row(std::span<const double>(values.begin(), values.size()));
  }

  const std::vector<std::string>& columns() const { return columns_; }
  /// Index of a column, or columns().size() when there is none of that name.
  std::size_t column_index(std::string_view name) const;
  std::size_t rows() const { return rows_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  void emit();

  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::unique_ptr<std::FILE, Closer> file_;
  std::string line_;
  std::size_t rows_ = 0;
};

}  // namespace rift
