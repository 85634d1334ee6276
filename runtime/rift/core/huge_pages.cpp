#include "rift/core/huge_pages.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rift {

namespace {
std::atomic<std::size_t> g_headroom_factor{2};
std::atomic<std::size_t> g_headroom_min_bytes{kHugePageAdviceBytes};
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

}  // namespace rift
