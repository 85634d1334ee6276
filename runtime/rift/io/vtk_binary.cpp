#include "rift/io/vtk_binary.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>

namespace rift::io {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

bool is_space(char c) {
  return c == ' ' || c == '\n' || c == '\r' || c == '\t';
}

// Hands out bytes from raw data or from base64 text. Base64 is decoded one
// group of four characters at a time, and a group with '=' padding simply
// yields fewer bytes: that reads VTK's separately encoded header and blocks as
// one stream.
class ByteSource {
 public:
  ByteSource(std::string_view data, bool base64) : data_(data), base64_(base64) {}

  // Bytes still available at most (exact for raw data, an upper bound for base64).
  std::size_t left_at_most() const {
    const std::size_t rest = data_.size() - pos_;
    return base64_ ? rest / 4 * 3 + 3 : rest;
  }

  void read(std::uint8_t* out, std::size_t n) {
    if (!base64_) {
      if (data_.size() - pos_ < n) throw VtkDataError("the data ends early");
      std::copy_n(data_.data() + pos_, n, out);
      pos_ += n;
      return;
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (pending_begin_ == pending_end_) refill();
      out[k] = pending_[pending_begin_++];
    }
  }

 private:
  void refill() {
    std::array<int, 4> v{};
    int got = 0, padding = 0;
    while (got < 4) {
      while (pos_ < data_.size() && is_space(data_[pos_]))
        ++pos_;
      if (pos_ >= data_.size()) throw VtkDataError("the base64 data ends early");
      const char c = data_[pos_++];
      if (c == '=') {
        if (got < 2) throw VtkDataError("misplaced '=' in the base64 data");
        ++padding;
        v[static_cast<std::size_t>(got++)] = 0;
        continue;
      }
      if (padding > 0) throw VtkDataError("misplaced '=' in the base64 data");
      const int value = base64_value(c);
      if (value < 0) {
        throw VtkDataError(std::string("character ") +
                           (c >= 32 && c < 127
                                ? std::string("'") + c + "'"
                                : "code " + std::to_string(static_cast<unsigned char>(c))) +
                           " is not base64");
      }
      v[static_cast<std::size_t>(got++)] = value;
    }
    const std::uint32_t bits =
        (static_cast<std::uint32_t>(v[0]) << 18) | (static_cast<std::uint32_t>(v[1]) << 12) |
        (static_cast<std::uint32_t>(v[2]) << 6) | static_cast<std::uint32_t>(v[3]);
    pending_ = {static_cast<std::uint8_t>(bits >> 16), static_cast<std::uint8_t>(bits >> 8),
                static_cast<std::uint8_t>(bits)};
    pending_begin_ = 0;
    pending_end_ = 3 - padding;
  }

  std::string_view data_;
  bool base64_;
  std::size_t pos_ = 0;
  std::array<std::uint8_t, 3> pending_{};
  int pending_begin_ = 0, pending_end_ = 0;
};

std::uint64_t header_integer(ByteSource& in, const VtkBinaryLayout& layout) {
  std::array<std::uint8_t, 8> b{};
  // UInt64 or UInt32 (the reader sets nothing else); spelled as a choice so
  // that the compiler sees the read fits in b.
  const std::size_t n = layout.header_bytes == 8 ? 8 : 4;
  in.read(b.data(), n);
  std::uint64_t value = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t byte = layout.big_endian ? k : n - 1 - k;
    value = (value << 8) | b[byte];
  }
  return value;
}

// zlib cannot compress better than about 1032:1; a header claiming more is a lie.
constexpr std::uint64_t kMaxZlibRatio = 1032;

}  // namespace

std::vector<std::uint8_t> decode_vtk_array(std::string_view data, const VtkBinaryLayout& layout) {
  ByteSource in(data, layout.base64);
  if (!layout.compressed) {
    const std::uint64_t size = header_integer(in, layout);
    if (size > in.left_at_most()) {
      throw VtkDataError("the header announces " + std::to_string(size) + " bytes, but only " +
                         std::to_string(in.left_at_most()) + " follow");
    }
    std::vector<std::uint8_t> out(static_cast<std::size_t>(size));
    in.read(out.data(), out.size());
    return out;
  }
  const std::uint64_t blocks = header_integer(in, layout);
  const std::uint64_t block_size = header_integer(in, layout);
  const std::uint64_t last_size = header_integer(in, layout);
  const std::uint64_t header_left =
      in.left_at_most() / static_cast<std::size_t>(layout.header_bytes);
  if (blocks > header_left) {
    throw VtkDataError("the compression header announces " + std::to_string(blocks) +
                       " blocks, more than the data can hold");
  }
  if (last_size > block_size) {
    throw VtkDataError("the last compressed block (" + std::to_string(last_size) +
                       " bytes) is larger than the block size (" + std::to_string(block_size) +
                       ")");
  }
  std::vector<std::uint64_t> compressed(static_cast<std::size_t>(blocks));
  std::uint64_t total_compressed = 0;
  for (std::uint64_t& c : compressed) {
    c = header_integer(in, layout);
    total_compressed += std::min<std::uint64_t>(c, in.left_at_most());
  }
  if (blocks == 0) return {};
  const std::uint64_t last = last_size == 0 ? block_size : last_size;
  const std::uint64_t total = (blocks - 1) * block_size + last;
  if (block_size == 0 || total > kMaxZlibRatio * (total_compressed + 64)) {
    throw VtkDataError("the compression header announces " + std::to_string(total) +
                       " bytes, more than the compressed data can hold");
  }
  std::vector<std::uint8_t> out(static_cast<std::size_t>(total));
  std::vector<std::uint8_t> block;
  for (std::size_t b = 0; b < compressed.size(); ++b) {
    if (compressed[b] > in.left_at_most()) {
      throw VtkDataError("compressed block " + std::to_string(b + 1) + " announces " +
                         std::to_string(compressed[b]) + " bytes, but fewer follow");
    }
    block.resize(static_cast<std::size_t>(compressed[b]));
    in.read(block.data(), block.size());
    const std::uint64_t expected = b + 1 == compressed.size() ? last : block_size;
    uLongf produced = static_cast<uLongf>(expected);
    const int status = uncompress(out.data() + b * block_size, &produced, block.data(),
                                  static_cast<uLong>(block.size()));
    if (status != Z_OK || produced != expected) {
      throw VtkDataError("compressed block " + std::to_string(b + 1) + " of " +
                         std::to_string(compressed.size()) + " does not inflate to " +
                         std::to_string(expected) + " bytes (" +
                         (status == Z_OK ? "it gives " + std::to_string(produced)
                                         : std::string("zlib: ") + zError(status)) +
                         ")");
    }
  }
  return out;
}

void append_base64(std::string& out, const std::uint8_t* bytes, std::size_t size) {
  for (std::size_t k = 0; k < size; k += 3) {
    const std::size_t n = std::min<std::size_t>(3, size - k);
    std::uint32_t bits = static_cast<std::uint32_t>(bytes[k]) << 16;
    if (n > 1) bits |= static_cast<std::uint32_t>(bytes[k + 1]) << 8;
    if (n > 2) bits |= bytes[k + 2];
    out += kAlphabet[(bits >> 18) & 63];
    out += kAlphabet[(bits >> 12) & 63];
    out += n > 1 ? kAlphabet[(bits >> 6) & 63] : '=';
    out += n > 2 ? kAlphabet[bits & 63] : '=';
  }
}

std::vector<std::uint8_t> vtk_zlib_blocks(const std::uint8_t* bytes, std::size_t size,
                                          int header_bytes, std::size_t block_size) {
  const std::size_t blocks = (size + block_size - 1) / block_size;
  std::vector<std::uint64_t> header = {blocks, block_size,
                                       blocks == 0 ? 0 : size - (blocks - 1) * block_size};
  std::vector<std::uint8_t> body;
  std::vector<std::uint8_t> block;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t n = std::min(block_size, size - b * block_size);
    uLongf room = compressBound(static_cast<uLong>(n));
    block.resize(room);
    compress2(block.data(), &room, bytes + b * block_size, static_cast<uLong>(n), Z_BEST_SPEED);
    header.push_back(room);
    body.insert(body.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(room));
  }
  std::vector<std::uint8_t> out;
  for (const std::uint64_t h : header) {
    for (int k = 0; k < header_bytes; ++k)
      out.push_back(static_cast<std::uint8_t>(h >> (8 * k)));
  }
  out.insert(out.end(), body.begin(), body.end());
  return out;
}

}  // namespace rift::io
