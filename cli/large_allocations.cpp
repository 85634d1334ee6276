// Every large allocation of a simulator's process in transparent huge pages.
//
// The kernel backs memory with 2 MiB pages only where it was advised
// (transparent_hugepage=madvise, Debian's default). The runtime advises the
// arrays it grows itself (rift/core/huge_pages.hpp), but a 10^6-vertex
// set-up allocates many more: the match caches' groups and hash tables, the
// scatter colouring, the integrator's arrays, sorted copies and scratch. Each
// such array was then faulted in 4 KiB at a time, and on a virtual machine a
// 4 KiB fault with its page clearing costs about 8x a 2 MiB fault per byte
// (5 s against 0.6 s per GiB measured on the project's machine): a quarter of
// the set-up of the 10^6-hexahedron block (docs/performance.md, "Every large
// allocation in huge pages").
//
// The global operator new and delete of the executables that link rift_cli
// (rift and every rift_add_simulator program) are replaced here: an
// allocation of kHugePageAdviceBytes or more is advised before anything
// touches it. Only the pages written become resident, as before; a large
// block that is reserved but barely filled may hold up to 2 MiB more. The
// values computed do not depend on it. Sanitizer builds keep the sanitizer's
// own operator new, which checks new/delete pairing.
//
// glibc serves a block above its mmap threshold with a mapping of its own,
// unmapped when freed, and one below it from its heap, which keeps the pages
// of freed blocks resident. The threshold starts at 128 KiB and rises to the
// size of each mapped block freed, up to 32 MiB: after the set-up's first
// large arrays come and go, its transient arrays of 4 to 32 MiB (a sort's
// buckets, a build's scratch) stay resident once freed, 30 to 55 MB at 10^6
// quads (peak 861 MB against 806 MB with a fixed threshold, measured). A
// threshold set by mallopt stays where it is set: here, at the size from
// which blocks are advised for huge pages, so that every such block is a
// mapping of its own and freeing it gives it back.
#include <cstdlib>
#include <new>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli/large_allocations.hpp"
#include "rift/core/huge_pages.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define RIFT_SANITIZED_ALLOCATOR 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RIFT_SANITIZED_ALLOCATOR 1
#endif

namespace rift::cli {

bool large_allocations_in_huge_pages() {
#ifdef RIFT_SANITIZED_ALLOCATOR
  return false;
#else
  return true;
#endif
}

void give_large_blocks_back_when_freed() {
#if defined(__GLIBC__) && !defined(RIFT_SANITIZED_ALLOCATOR)
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(rift::kHugePageAdviceBytes));
#endif
}

}  // namespace rift::cli

#ifndef RIFT_SANITIZED_ALLOCATOR

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

/// A large block starts on a huge page and spans whole huge pages: malloc's
/// own blocks start 16 bytes into a mapping the kernel places anywhere, so
/// their first and last 2 MiB (the parts no huge page fits in) were faulted
/// 4 KiB at a time, about 1000 faults per array.
void* allocate_large(std::size_t bytes) {
  const std::size_t whole = (bytes + kHugePage - 1) & ~(kHugePage - 1);
  void* p = nullptr;
  if (posix_memalign(&p, kHugePage, whole) != 0) return nullptr;
  rift::advise_huge_pages(p, whole);
  return p;
}

void* allocate(std::size_t bytes) {
  if (bytes == 0) bytes = 1;
  for (;;) {
    if (void* p =
            bytes >= rift::kHugePageAdviceBytes ? allocate_large(bytes) : std::malloc(bytes)) {
      return p;
    }
    // The standard's loop: a new-handler may free memory, or throw.
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

// libstdc++'s nothrow and aligned-less forms call these; every block is
// malloc's (posix_memalign's included), so free gives each back.
void* operator new(std::size_t bytes) {
  return allocate(bytes);
}
void* operator new[](std::size_t bytes) {
  return allocate(bytes);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t /*bytes*/) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t /*bytes*/) noexcept {
  std::free(p);
}

#endif
