#include "rift/output/png_writer.hpp"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rift/output/file_sink.hpp"

namespace rift {

namespace {

struct PngSink {
  std::vector<std::uint8_t>* bytes;
  bool out_of_memory;
  char message[256];
};

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  if (sink->out_of_memory) return;
  try {
    sink->bytes->insert(sink->bytes->end(), data, data + size);
  } catch (...) {
    sink->out_of_memory = true;  // reported after libpng returns, never thrown through C
  }
}

void flush_nothing(png_structp) {}

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  std::strncpy(sink->message, message ? message : "unknown error", sizeof sink->message - 1);
  sink->message[sizeof sink->message - 1] = '\0';
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// Only trivially destructible objects live between setjmp and png_longjmp.
bool encode(const Image& image, PngSink& sink, png_bytep* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &sink, append_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_text text{};
  char key[] = "Software";
  char value[] = "rift";
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = key;
  text.text = value;
  png_set_text(png, info, &text, 1);
  // Flat-shaded renders compress well already at a fast level.
  png_set_compression_level(png, 3);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() !=
          3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    throw std::invalid_argument("encode_png: the image has no pixels or a wrong buffer size");
  }
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.rgb.size() / 4 + 1024);
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    // libpng's row pointers are non-const but png_write_image only reads them.
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(
        image.rgb.data() + 3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width));
  }
  PngSink sink{&bytes, false, "could not create the libpng writer"};
  if (!encode(image, sink, rows.data())) {
    throw std::runtime_error(std::string("PNG encoding failed: ") + sink.message);
  }
  if (sink.out_of_memory) throw std::runtime_error("PNG encoding failed: out of memory");
  return bytes;
}

void write_png(const Image& image, const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  write_file_atomically(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace rift
