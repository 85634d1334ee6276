// ParaView collection (.pvd): the list of frame files with their times, which
// ParaView opens as one time series. Rewritten after every frame through a
// temporary file and a rename, so a crash leaves a complete collection of the
// frames written so far.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace rift {

class PvdWriter {
 public:
  /// Writes an empty collection at `path` (replacing an older one), so the
  /// output folder is valid from the start. Throws OutputError.
  explicit PvdWriter(std::filesystem::path path);

  /// Appends a dataset (`file` relative to the PVD's folder, e.g.
  /// "frame_000003.vtu") at `time` and rewrites the collection.
  void add(double time, std::string_view file);

  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const { return count_; }

 private:
  void rewrite();

  std::filesystem::path path_;
  std::string entries_;  // the <DataSet .../> lines so far
  std::string text_;
  std::size_t count_ = 0;
};

}  // namespace rift
