// A hint that a cache line will be read soon, kept by the compiler.
//
// A tear on a large map reads a few hundred entries of arrays far from the
// caches (matches, their groups, slots). Asked for in a pass ahead of the work
// that reads them, their misses overlap instead of following one another.
// GCC 12 deletes a loop whose only effect is __builtin_prefetch when it
// inlines that loop next to another such loop (-ffinite-loops treats the
// loops as free of side effects): on x86-64 the hint is a volatile asm, which
// stays where it is written.
#pragma once

#include <cstddef>

namespace rift {

/// Maps with fewer darts keep their per-dart arrays (4 bytes a dart each, 2 MiB
/// here) near the caches, where a pass of hints costs more than it saves: a
/// 10x10 cloth's tear took 6 % longer with them, a 1000x1000 cloth's 0.80x
/// the time (docs/performance.md, "One tear as the loop pays it").
inline constexpr std::size_t kPrefetchFromDarts = std::size_t{1} << 19;

inline void prefetch(const void* address) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(address)));
#else
  __builtin_prefetch(address);
#endif
}

}  // namespace rift
