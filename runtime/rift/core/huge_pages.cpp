#include "rift/core/huge_pages.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>

#include "rift/core/parallel.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rift {

namespace {
std::atomic<std::size_t> g_headroom_factor{2};
std::atomic<std::size_t> g_headroom_min_bytes{kHugePageAdviceBytes};
// Cleared when the kernel refuses MADV_POPULATE_WRITE (older than 5.14):
// later calls skip the system call.
std::atomic<bool> g_populate_supported{true};
}  // namespace

std::size_t headroom_factor() {
  return g_headroom_factor.load(std::memory_order_relaxed);
}

std::size_t headroom_min_bytes() {
  return g_headroom_min_bytes.load(std::memory_order_relaxed);
}

void set_headroom_factor(std::size_t factor, std::size_t min_bytes) {
  g_headroom_factor.store(std::max<std::size_t>(factor, 1), std::memory_order_relaxed);
  g_headroom_min_bytes.store(min_bytes, std::memory_order_relaxed);
}

void advise_huge_pages([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);  // NOLINT(performance-no-int-to-ptr)
  const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
  if (last <= first) return;
  // A refusal (an old kernel, THP disabled) only loses the speed-up.
  madvise(reinterpret_cast<void*>(first), last - first,  // NOLINT(performance-no-int-to-ptr)
          MADV_HUGEPAGE);
#endif
}

void populate_for_write([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__)
#ifndef MADV_POPULATE_WRITE
  constexpr int MADV_POPULATE_WRITE = 23;  // Linux 5.14, older C library headers
#endif
  if (bytes < kPopulateMinBytes || thread_count() < 2) return;
  if (!g_populate_supported.load(std::memory_order_relaxed)) return;
  // Chunks of whole huge pages (two threads never share one), from the page
  // holding the first byte to the one holding the last: the advice only
  // faults pages in, so the bytes of those pages outside the range keep
  // their contents.
  constexpr std::uintptr_t kPage = 4096;
  constexpr std::uintptr_t kChunk = std::uintptr_t{2} << 20;
  const auto at = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = at & ~(kPage - 1);
  const std::uintptr_t end = (at + bytes + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t first_chunk = begin & ~(kChunk - 1);
  const std::size_t chunks = (end - first_chunk + kChunk - 1) / kChunk;
  auto populate = [&](std::size_t a, std::size_t b) {
    const std::uintptr_t from = std::max(begin, first_chunk + a * kChunk);
    const std::uintptr_t to = std::min(end, first_chunk + b * kChunk);
    if (!g_populate_supported.load(std::memory_order_relaxed)) return;
    // NOLINTNEXTLINE(performance-no-int-to-ptr)
    if (madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE) != 0 &&
        errno == EINVAL) {
      g_populate_supported.store(false, std::memory_order_relaxed);
    }
    // Any other refusal (no memory left) is met again, and reported, by the
    // write that follows.
  };
  parallel_blocks(chunks, 2, populate);
#endif
}

}  // namespace rift
