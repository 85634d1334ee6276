// Animated GIF (GIF89a) of rendered frames, written as they come so that an
// interrupted run keeps a playable file up to its last frame (the trailer is
// rewritten after every frame). Colours map to a fixed 6x7x6 palette (the
// renderer's flat shading survives it well) and are LZW-coded as the GIF
// specification says; no dithering.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "rift/output/renderer.hpp"

namespace rift {

/// The whole GIF of `frames` in memory (all of the same size), `delay_ms`
/// between frames, looping forever.
std::vector<std::uint8_t> encode_gif(const std::vector<const Image*>& frames, int delay_ms);

class GifWriter {
 public:
  /// Throws OutputError when the file cannot be created.
  GifWriter(std::filesystem::path path, int delay_ms);
  /// Appends a frame; the first one fixes the size (later ones must match).
  void add(const Image& image);
  std::size_t frames() const { return frames_; }

 private:
  std::filesystem::path path_;
  int delay_ms_;
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> bytes_;  // header and frames, without the trailer
  std::size_t frames_ = 0;
};

/// The palette index of an RGB colour (6 levels of red, 7 of green, 6 of blue).
std::uint8_t gif_palette_index(std::uint8_t r, std::uint8_t g, std::uint8_t b);

}  // namespace rift
