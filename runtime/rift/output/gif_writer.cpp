#include "rift/output/gif_writer.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

#include "rift/output/file_sink.hpp"

namespace rift {

namespace {

constexpr int kRed = 6, kGreen = 7, kBlue = 6;

void put16(std::vector<std::uint8_t>& out, int v) {
  out.push_back(static_cast<std::uint8_t>(v & 0xff));
  out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
}

void header(std::vector<std::uint8_t>& out, int width, int height) {
  for (char c : std::string("GIF89a"))
    out.push_back(static_cast<std::uint8_t>(c));
  put16(out, width);
  put16(out, height);
  out.push_back(0xf7);  // global colour table of 256 entries, 8 bits per primary
  out.push_back(0);     // background colour index
  out.push_back(0);     // square pixels
  for (int i = 0; i < 256; ++i) {
    const int r = i % kRed, g = (i / kRed) % kGreen, b = i / (kRed * kGreen);
    const bool used = i < kRed * kGreen * kBlue;
    out.push_back(used ? static_cast<std::uint8_t>(r * 255 / (kRed - 1)) : 0);
    out.push_back(used ? static_cast<std::uint8_t>(g * 255 / (kGreen - 1)) : 0);
    out.push_back(used ? static_cast<std::uint8_t>(b * 255 / (kBlue - 1)) : 0);
  }
  // NETSCAPE2.0 application extension: loop forever.
  const std::uint8_t loop[] = {0x21, 0xff, 0x0b, 'N', 'E',  'T',  'S',  'C',  'A', 'P',
                               'E',  '2',  '.',  '0', 0x03, 0x01, 0x00, 0x00, 0x00};
  out.insert(out.end(), std::begin(loop), std::end(loop));
}

// Variable-width LZW codes, least significant bit first, in sub-blocks of
// at most 255 bytes (GIF89a, appendix F).
class CodeStream {
 public:
  explicit CodeStream(std::vector<std::uint8_t>& out) : out_(out) {}
  void put(int code, int width) {
    bits_ |= static_cast<std::uint32_t>(code) << count_;
    count_ += width;
    while (count_ >= 8) {
      byte(static_cast<std::uint8_t>(bits_ & 0xff));
      bits_ >>= 8;
      count_ -= 8;
    }
  }
  void finish() {
    if (count_ > 0) byte(static_cast<std::uint8_t>(bits_ & 0xff));
    if (!block_.empty()) flush();
    out_.push_back(0);  // block terminator
  }

 private:
  void byte(std::uint8_t b) {
    block_.push_back(b);
    if (block_.size() == 255) flush();
  }
  void flush() {
    out_.push_back(static_cast<std::uint8_t>(block_.size()));
    out_.insert(out_.end(), block_.begin(), block_.end());
    block_.clear();
  }
  std::vector<std::uint8_t>& out_;
  std::vector<std::uint8_t> block_;
  std::uint32_t bits_ = 0;
  int count_ = 0;
};

void frame(std::vector<std::uint8_t>& out, const Image& image, int delay_ms) {
  // Graphic control extension: the delay in hundredths of a second.
  out.insert(out.end(), {0x21, 0xf9, 0x04, 0x00});
  put16(out, std::max(1, delay_ms / 10));
  out.insert(out.end(), {0x00, 0x00});
  // Image descriptor: the whole canvas, no local table.
  out.push_back(0x2c);
  put16(out, 0);
  put16(out, 0);
  put16(out, image.width);
  put16(out, image.height);
  out.push_back(0);
  const int min_code_size = 8;
  out.push_back(min_code_size);
  const int clear = 1 << min_code_size, end = clear + 1;
  // The dictionary as a trie: next[code * 256 + byte] is the code of that
  // string extended by `byte` (0: none yet).
  std::vector<std::uint16_t> next(std::size_t{4096} * 256, 0);
  CodeStream codes(out);
  int width = min_code_size + 1;
  int free_code = end + 1;
  codes.put(clear, width);
  const std::size_t n =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  int prefix = -1;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint8_t c =
        gif_palette_index(image.rgb[3 * k], image.rgb[3 * k + 1], image.rgb[3 * k + 2]);
    if (prefix < 0) {
      prefix = c;
      continue;
    }
    std::uint16_t& slot = next[static_cast<std::size_t>(prefix) * 256 + c];
    if (slot != 0) {
      prefix = slot;
      continue;
    }
    codes.put(prefix, width);
    if (free_code < 4096) {
      slot = static_cast<std::uint16_t>(free_code);
      // The decoder widens its codes once it has assigned 2^width of them.
      if (free_code == (1 << width) && width < 12) ++width;
      ++free_code;
    } else {
      // Full dictionary: start over.
      codes.put(clear, width);
      std::fill(next.begin(), next.end(), 0);
      width = min_code_size + 1;
      free_code = end + 1;
    }
    prefix = c;
  }
  if (prefix >= 0) codes.put(prefix, width);
  codes.put(end, width);
  codes.finish();
}

}  // namespace

std::uint8_t gif_palette_index(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const int ri = (r * (kRed - 1) + 127) / 255;
  const int gi = (g * (kGreen - 1) + 127) / 255;
  const int bi = (b * (kBlue - 1) + 127) / 255;
  return static_cast<std::uint8_t>(ri + kRed * (gi + kGreen * bi));
}

std::vector<std::uint8_t> encode_gif(const std::vector<const Image*>& frames, int delay_ms) {
  if (frames.empty()) throw std::invalid_argument("a GIF needs at least one frame");
  std::vector<std::uint8_t> out;
  header(out, frames.front()->width, frames.front()->height);
  for (const Image* image : frames) {
    if (image->width != frames.front()->width || image->height != frames.front()->height)
      throw std::invalid_argument("every frame of a GIF must have the same size");
    frame(out, *image, delay_ms);
  }
  out.push_back(0x3b);
  return out;
}

GifWriter::GifWriter(std::filesystem::path path, int delay_ms)
    : path_(std::move(path)), delay_ms_(delay_ms) {}

void GifWriter::add(const Image& image) {
  if (frames_ == 0) {
    width_ = image.width;
    height_ = image.height;
    header(bytes_, width_, height_);
  } else if (image.width != width_ || image.height != height_) {
    throw std::invalid_argument("every frame of a GIF must have the same size");
  }
  frame(bytes_, image, delay_ms_);
  ++frames_;
  std::vector<std::uint8_t> file = bytes_;
  file.push_back(0x3b);
  write_file_atomically(path_,
                        std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
}

}  // namespace rift
