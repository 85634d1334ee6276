#pragma once

#include <bit>
#include <cstdint>

#include "rift/core/types.hpp"

namespace rift::test {

/// Bit-for-bit equality of two reals: unlike ==, it tells -0 from +0 and
/// sees a NaN equal to itself, as byte-identical outputs require.
inline bool same_bits(Real a, Real b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

}  // namespace rift::test
