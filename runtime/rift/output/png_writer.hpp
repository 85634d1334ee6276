// PNG encoding of rendered images with libpng.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "rift/output/renderer.hpp"

namespace rift {

/// The PNG file bytes of `image` (8-bit RGB). Throws std::runtime_error with
/// libpng's message if encoding fails.
std::vector<std::uint8_t> encode_png(const Image& image);

/// Encodes `image` and writes it to `path` atomically. Throws OutputError.
void write_png(const Image& image, const std::filesystem::path& path);

}  // namespace rift
