#include "rift/output/frame_outputs.hpp"

#include <stdexcept>

#include "rift/output/file_sink.hpp"
#include "rift/output/png_writer.hpp"

namespace rift {

FrameOutputs::FrameOutputs(OutputConfig config)
    : config_(std::move(config)),
      extractor_(config_.frame),
      vtu_(config_.vtu_encoding),
      renderer_(config_.render) {
  if (config_.png_every < 1) throw std::invalid_argument("png_every must be at least 1");
  ensure_directory(config_.directory);
  if (config_.vtu) pvd_.emplace(config_.directory / (config_.name + ".pvd"));
  if (config_.gif) gif_.emplace(config_.directory / (config_.name + ".gif"), config_.gif_delay_ms);
  if (!config_.csv_columns.empty()) {
    csv_.emplace(config_.directory / (config_.name + ".csv"), config_.csv_columns);
  }
}

const FrameMesh& FrameOutputs::write_frame(const GMap& map, double time, const FrameMesh* scenery) {
  FrameOptions& options = extractor_.options();
  if (frames_ == 0 && config_.boundary_from_first_frame && options.original_boundary.empty() &&
      options.torn_darts.empty()) {
    original_boundary_ = record_boundary_darts(map);
    options.original_boundary = original_boundary_;
  }
  const FrameMesh& frame = extractor_.extract(map);
  const std::size_t index = frames_;
  if (pvd_) {  // exists exactly when config_.vtu
    const std::string file = frame_file_name("frame_", index, "vtu");
    vtu_.write(frame, config_.directory / file, time);
    pvd_->add(time, file);
    if (scenery) {
      if (!scenery_pvd_)
        scenery_pvd_.emplace(config_.directory / (config_.name + "_obstacles.pvd"));
      const std::string props = frame_file_name("obstacles_", index, "vtu");
      vtu_.write(*scenery, config_.directory / props, time);
      scenery_pvd_->add(time, props);
    }
  }
  if (config_.obj) obj_.write(frame, config_.directory / frame_file_name("frame_", index, "obj"));
  if ((config_.png || config_.gif) && index % static_cast<std::size_t>(config_.png_every) == 0) {
    using Mode = OutputConfig::Camera;
    Vec3 lo, hi;
    if (config_.camera != Mode::kFixed && frame.bounding_box(lo, hi)) {
      seen_lo_ = seen_lo_.cwiseMin(lo);
      seen_hi_ = seen_hi_.cwiseMax(hi);
      const Real aspect = static_cast<Real>(config_.render.width) / config_.render.height;
      if (config_.camera == Mode::kFollow) {
        camera_ = renderer_.frame_camera(frame, config_.view);
      } else {
        camera_ = Camera::framing(seen_lo_, seen_hi_, aspect, config_.view);
      }
    }
    if (!camera_) camera_ = renderer_.frame_camera(frame, config_.view);
    const Image& image = renderer_.render(frame, *camera_, scenery);
    if (config_.png) write_png(image, config_.directory / frame_file_name("frame_", index, "png"));
    if (gif_) gif_->add(image);
  }
  ++frames_;
  return frame;
}

void FrameOutputs::write_statistics(std::span<const double> row) {
  if (!csv_) throw std::logic_error("write_statistics: no CSV columns were configured");
  csv_->write_row(row);
}

void FrameOutputs::remap_darts(const std::vector<Dart>& new_index) {
  if (original_boundary_.empty()) return;
  original_boundary_ = remap_dart_flags(original_boundary_, new_index);
  extractor_.options().original_boundary = original_boundary_;
}

}  // namespace rift
