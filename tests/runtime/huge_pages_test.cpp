// Growth headroom of the large arrays (rift/core/huge_pages.hpp, issue 12):
// a buffer given by reserve_huge, grow_huge or push_back_huge has room for
// headroom_factor() times what was asked, so growing within it keeps the
// buffer (no copy), and growing past it moves the values intact.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "rift/core/huge_pages.hpp"

namespace rift {
namespace {

/// Restores the default factor when a test ends, even a failed one.
struct FactorGuard {
  std::size_t saved = headroom_factor();
  std::size_t saved_min = headroom_min_bytes();
  ~FactorGuard() { set_headroom_factor(saved, saved_min); }
};

// Large enough to be advised for huge pages (2^21 x 4 bytes = 8 MiB).
constexpr std::size_t kLarge = std::size_t{1} << 21;

TEST(HugeArrays, GrowthWithinTheHeadroomKeepsTheBuffer) {
  const FactorGuard guard;
  set_headroom_factor(2, 0);  // small arrays too
  for (std::size_t n : {std::size_t{100}, kLarge}) {
    std::vector<std::uint32_t> v;
    grow_huge(v, n, 7u);
    ASSERT_EQ(v.size(), n);
    EXPECT_GE(v.capacity(), 2 * n);
    const std::uint32_t* before = v.data();
    grow_huge(v, 2 * n - 1, 8u);
    push_back_huge(v, 9u);
    EXPECT_EQ(v.data(), before) << n;
    EXPECT_EQ(v[n - 1], 7u);
    EXPECT_EQ(v[n], 8u);
    EXPECT_EQ(v[2 * n - 1], 9u);
  }
}

TEST(HugeArrays, GrowthPastTheHeadroomMovesTheValues) {
  const FactorGuard guard;
  set_headroom_factor(2);
  std::vector<std::uint32_t> v;
  reserve_huge(v, kLarge);
  for (std::uint32_t k = 0; k < 2 * kLarge; ++k)
    push_back_huge(v, k);
  const std::uint32_t* before = v.data();
  push_back_huge(v, 12345u);  // the first element past the headroom
  EXPECT_NE(v.data(), before);
  ASSERT_EQ(v.size(), 2 * kLarge + 1);
  for (std::uint32_t k = 0; k < 2 * kLarge; ++k)
    ASSERT_EQ(v[k], k);
  EXPECT_EQ(v.back(), 12345u);
  // Past the headroom the capacity at least doubles again.
  EXPECT_GE(v.capacity(), 4 * kLarge);
}

TEST(HugeArrays, FactorOneGivesExactBuffersThatStillGrowGeometrically) {
  const FactorGuard guard;
  set_headroom_factor(1, 0);
  std::vector<double> v;
  grow_huge(v, 1000, 1.0);
  EXPECT_EQ(v.capacity(), 1000u);
  grow_huge(v, 1001, 2.0);
  EXPECT_EQ(v.capacity(), 2000u);
  EXPECT_EQ(v[999], 1.0);
  EXPECT_EQ(v[1000], 2.0);
  set_headroom_factor(0);  // clamped: never less than the elements asked for
  EXPECT_EQ(headroom_factor(), 1u);
}

// An array filled element by element (its last regrow may have left it
// full) gets its headroom at once, and keeps its values; a small one, with
// the default threshold, stays as it is.
TEST(HugeArrays, ReserveHeadroomGivesAFilledArrayItsRoom) {
  const FactorGuard guard;
  set_headroom_factor(3);
  std::vector<std::uint32_t> v(kLarge);
  for (std::uint32_t k = 0; k < kLarge; ++k)
    v[k] = k;
  ASSERT_LT(v.capacity(), 3 * kLarge);
  reserve_headroom(v);
  EXPECT_GE(v.capacity(), 3 * kLarge);
  ASSERT_EQ(v.size(), kLarge);
  for (std::uint32_t k = 0; k < kLarge; ++k)
    ASSERT_EQ(v[k], k);
  const std::uint32_t* moved = v.data();
  reserve_headroom(v);  // already has it: keeps its buffer
  EXPECT_EQ(v.data(), moved);
  std::vector<std::uint32_t> small(100, 1u);
  reserve_headroom(small);
  EXPECT_EQ(small.capacity(), 100u);
}

// By default only large arrays get headroom: a small one's spare room would
// be memory (malloc's heap), and copying it is cheap.
TEST(HugeArrays, ASmallArrayGetsExactlyWhatItAsksFor) {
  const FactorGuard guard;
  set_headroom_factor(2);
  EXPECT_EQ(headroom_min_bytes(), kHugePageAdviceBytes);
  std::vector<std::uint32_t> small;
  reserve_huge(small, 1000);
  EXPECT_EQ(small.capacity(), 1000u);
  std::vector<std::uint32_t> large;
  reserve_huge(large, kLarge);
  EXPECT_GE(large.capacity(), 2 * kLarge);
}

}  // namespace
}  // namespace rift
