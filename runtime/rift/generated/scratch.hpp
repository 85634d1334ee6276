// Buffers reused by the code riftc generates (matching, rewriting, orbit
// aggregates), one set per thread: after warm-up, matching and rewriting do
// not allocate. Each user touches only its own fields and leaves them empty
// or reset, so the same set serves every pack.
#pragma once

#include <cstdint>
#include <vector>

#include "rift/core/types.hpp"

namespace rift::generated {

inline constexpr std::uint32_t kNoRow = 0xFFFFFFFFu;

struct Scratch {
  std::vector<std::uint64_t> row_index;  // (dart << 32) | row of the orbit being built, hashed
  std::vector<Dart> rows;                // hook j's dart of row r at rows[j * row_count + r]
  std::vector<std::uint32_t> nbr;        // nbr[r * label + k]: row reached from r by hook link k
  std::vector<std::uint32_t> parent;  // parent[r] = p * label + k: r was reached from p by link k
  std::vector<Dart> left;             // left node v's dart of row r at left[v * row_count + r]
  std::vector<Dart> right;            // the same for right nodes
  std::vector<Dart> orbit;
  std::vector<Dart> marked;
  std::vector<Slot> slots;
  std::vector<Slot> claimed;
  std::vector<Slot> seen;
};

/// This thread's buffers.
Scratch& scratch();

}  // namespace rift::generated
