// The binary encodings of VTK XML data arrays, as ParaView and VTK write them:
// inline base64 (format="binary") and appended data (raw bytes or base64 after
// <AppendedData>'s '_'), each optionally zlib-compressed (vtkZLibDataCompressor).
//
// Layout of one array's bytes, with header integers of `header_bytes` (UInt32:
// 4, UInt64: 8) in the file's byte order:
//   uncompressed: [byte count][data]
//   compressed:   [block count][block size][last block size][compressed size
//                  of each block][each block, zlib-compressed]
// In base64 the compressed header is encoded separately from the blocks; a
// decoder that takes the text four characters at a time reads both forms.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rift::io {

/// What is wrong with an array's bytes; the VTU reader adds the file and line.
class VtkDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How one DataArray's bytes are stored.
struct VtkBinaryLayout {
  bool base64 = false;      ///< else raw bytes
  bool compressed = false;  ///< vtkZLibDataCompressor
  int header_bytes = 4;     ///< 4 (UInt32) or 8 (UInt64)
  bool big_endian = false;
};

/// Decodes one array starting at the beginning of `data` (base64 text or raw
/// bytes; it may run on past the array). Returns the uncompressed bytes.
/// Memory is bounded by the data present: a header claiming more bytes than
/// `data` holds (or, compressed, more than zlib's largest ratio allows) is an
/// error, never an allocation.
/// Throws VtkDataError.
std::vector<std::uint8_t> decode_vtk_array(std::string_view data, const VtkBinaryLayout& layout);

/// Base64 encoding (RFC 4648, with padding), for writers and tests.
void append_base64(std::string& out, const std::uint8_t* bytes, std::size_t size);

/// zlib-compresses `size` bytes in VTK's block layout with a UInt32 or UInt64
/// header (for tests and writers). Returns the header followed by the blocks.
std::vector<std::uint8_t> vtk_zlib_blocks(const std::uint8_t* bytes, std::size_t size,
                                          int header_bytes, std::size_t block_size = 32768);

}  // namespace rift::io
