// Everything a simulation writes per frame, behind one call: the loop builds
// a FrameOutputs once, then calls write_frame() for each output frame and
// write_statistics() for each CSV row. The frame is extracted once and shared
// by the VTU, OBJ and PNG writers; buffers are reused across frames.
//
//   out/
//     <name>.pvd              collection of every frame written (ParaView)
//     frame_000000.vtu ...    one unstructured grid per frame
//     frame_000000.obj ...    boundary surface per frame (when asked)
//     frame_000000.png ...    render of every png_every-th frame
//     <name>.csv              statistics, one row per call
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rift/output/camera.hpp"
#include "rift/output/csv_writer.hpp"
#include "rift/output/frame_mesh.hpp"
#include "rift/output/gif_writer.hpp"
#include "rift/output/obj_writer.hpp"
#include "rift/output/pvd_writer.hpp"
#include "rift/output/renderer.hpp"
#include "rift/output/vtu_writer.hpp"

namespace rift {

struct OutputConfig {
  std::filesystem::path directory = "out";
  std::string name = "frames";  ///< base name of the .pvd and .csv files
  bool vtu = true;
  VtuEncoding vtu_encoding = VtuEncoding::kAppendedBinary;
  bool obj = false;
  bool png = true;
  int png_every = 1;  ///< render every k-th frame written
  /// CSV columns (e.g. time, kinetic_energy, tears, step_ms); empty: no CSV.
  std::vector<std::string> csv_columns;
  FrameOptions frame;
  RenderOptions render;
  CameraView view;
  /// fixed: framed on the first rendered frame; follow: each frame's points;
  /// follow_union: every point rendered so far.
  enum class Camera { kFixed, kFollow, kFollowUnion } camera = Camera::kFixed;
  /// An animated GIF of the rendered frames (<name>.gif).
  bool gif = false;
  int gif_delay_ms = 80;
  /// When FrameOptions gives neither original_boundary nor torn_darts, the
  /// first frame's free darts are taken as the original boundary, so later
  /// free darts count as torn.
  bool boundary_from_first_frame = true;
};

class FrameOutputs {
 public:
  /// Creates the folder, an empty PVD and the CSV header. Throws OutputError.
  explicit FrameOutputs(OutputConfig config);

  /// Writes the next frame of `map` at simulation time `time` and returns it.
  /// `scenery` (obstacles) is drawn in PNGs and written as
  /// obstacles_NNNNNN.vtu, listed in <name>_obstacles.pvd.
  const FrameMesh& write_frame(const GMap& map, double time, const FrameMesh* scenery = nullptr);
  /// Appends one CSV row (one value per csv_columns entry).
  void write_statistics(std::span<const double> row);

  /// Renumbers the recorded original boundary after GMap::compact().
  void remap_darts(const std::vector<Dart>& new_index);

  std::size_t frames_written() const { return frames_; }
  const OutputConfig& config() const { return config_; }
  /// The camera fixed on the first rendered frame (nullopt before it).
  const std::optional<Camera>& camera() const { return camera_; }
  const FrameMesh& last_frame() const { return extractor_.frame(); }

 private:
  OutputConfig config_;
  FrameExtractor extractor_;
  std::vector<std::uint8_t> original_boundary_;
  std::optional<PvdWriter> pvd_, scenery_pvd_;
  std::optional<GifWriter> gif_;
  Vec3 seen_lo_ = Vec3::Constant(INFINITY), seen_hi_ = Vec3::Constant(-INFINITY);
  std::optional<CsvWriter> csv_;
  VtuWriter vtu_;
  ObjWriter obj_;
  Renderer renderer_;
  std::optional<Camera> camera_;
  std::size_t frames_ = 0;
};

}  // namespace rift
