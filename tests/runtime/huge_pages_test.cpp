// Growth headroom of the large arrays (rift/core/huge_pages.hpp, issue 12):
// a buffer given by reserve_huge, grow_huge or push_back_huge has room for
// headroom_factor() times what was asked, so growing within it keeps the
// buffer (no copy), and growing past it moves the values intact.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "rift/core/huge_pages.hpp"
#include "rift/core/parallel.hpp"

namespace rift {
namespace {

/// Restores the default factor when a test ends, even a failed one.
struct FactorGuard {
  std::size_t saved = headroom_factor();
  std::size_t saved_min = headroom_min_bytes();
  ~FactorGuard() { set_headroom_factor(saved, saved_min); }
};

/// Restores the thread count when a test ends.
struct ThreadsGuard {
  ~ThreadsGuard() { set_thread_count(0); }
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

#if defined(__linux__)
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23
#endif

/// A fresh anonymous mapping of `bytes`, none of its pages resident.
struct FreshPages {
  explicit FreshPages(std::size_t n) : bytes(n) {
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    data = p == MAP_FAILED ? nullptr : static_cast<char*>(p);
    // Pages of 4 KiB whatever the system's huge page setting: a write then
    // makes exactly its own page resident.
    if (data) madvise(data, bytes, MADV_NOHUGEPAGE);
  }
  ~FreshPages() {
    if (data) munmap(data, bytes);
  }
  FreshPages(const FreshPages&) = delete;
  FreshPages& operator=(const FreshPages&) = delete;
  /// Resident pages among [from, from + n) (mincore).
  std::size_t resident(std::size_t from, std::size_t n) const {
    const std::size_t page = 4096;
    std::vector<unsigned char> in((n + page - 1) / page);
    if (mincore(data + from, n, in.data()) != 0) return 0;
    std::size_t count = 0;
    for (unsigned char c : in)
      count += c & 1u;
    return count;
  }
  std::size_t bytes;
  char* data = nullptr;
};

bool kernel_populates() {
  const FreshPages probe(4096);
  return probe.data && madvise(probe.data, 4096, MADV_POPULATE_WRITE) == 0;
}

// The first write of a large array faults its pages in on every thread
// (populate_for_write), and only faults them in: bytes written before, in
// the pages at either end of an unaligned range, keep their values.
TEST(HugeArrays, PopulatingFaultsInEveryPageOfTheRangeAndWritesNothing) {
  if (!kernel_populates()) GTEST_SKIP() << "no MADV_POPULATE_WRITE (Linux < 5.14)";
  const ThreadsGuard guard;
  const std::size_t page = 4096;
  const std::size_t bytes = kPopulateMinBytes + 6 * page;
  FreshPages fresh(bytes);
  ASSERT_NE(fresh.data, nullptr);
  fresh.data[page + 10] = 'a';          // in the range's first page
  fresh.data[bytes - page - 20] = 'z';  // in its last page
  fresh.data[bytes - 5] = 'q';          // a page after it
  const std::size_t from = page + 100, to = bytes - page - 10;
  ASSERT_EQ(fresh.resident(2 * page, bytes - 4 * page), 0u);

  set_thread_count(1);
  populate_for_write(fresh.data + from, to - from);
  EXPECT_EQ(fresh.resident(2 * page, bytes - 4 * page), 0u) << "one thread: left to the write";

  set_thread_count(2);
  populate_for_write(fresh.data + from, to - from);
  const std::size_t inside = (bytes - 2 * page) / page;  // pages [page, bytes - page)
  EXPECT_EQ(fresh.resident(page, bytes - 2 * page), inside);
  EXPECT_EQ(fresh.data[page + 10], 'a');
  EXPECT_EQ(fresh.data[bytes - page - 20], 'z');
  EXPECT_EQ(fresh.data[bytes - 5], 'q');
  EXPECT_EQ(fresh.data[from], 0);

  // Below the threshold nothing is done.
  FreshPages small(kPopulateMinBytes / 2);
  ASSERT_NE(small.data, nullptr);
  populate_for_write(small.data, small.bytes);
  EXPECT_EQ(small.resident(0, small.bytes), 0u);
}

// A large array grown on two threads holds what it would on one.
TEST(HugeArrays, GrowthOnTwoThreadsKeepsAndFillsTheValues) {
  const ThreadsGuard guard;
  set_thread_count(2);
  const std::size_t n = 3 * kPopulateMinBytes / sizeof(std::uint64_t) + 5;
  std::vector<std::uint64_t> v;
  grow_huge(v, 1000, std::uint64_t{3});
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = i;
  grow_huge(v, n, std::uint64_t{7});  // a new buffer: populated, copied, filled
  ASSERT_EQ(v.size(), n);
  for (std::size_t i = 0; i < 1000; ++i)
    ASSERT_EQ(v[i], i);
  for (std::size_t i = 1000; i < n; ++i)
    ASSERT_EQ(v[i], 7u) << i;
  const std::uint64_t* before = v.data();
  grow_huge(v, n + n / 2, std::uint64_t{9});  // within the headroom: populated, filled
  EXPECT_EQ(v.data(), before);
  EXPECT_EQ(v[n - 1], 7u);
  EXPECT_EQ(v[n], 9u);
  EXPECT_EQ(v.back(), 9u);
}
#endif

}  // namespace
}  // namespace rift
