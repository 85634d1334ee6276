// The replacement operator new of allocation_watch.hpp. malloc/free pair
// with new/delete here by design (hence -Wno-mismatched-new-delete).
#include "allocation_watch.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_count{0};
std::atomic<std::size_t> g_largest{0};
}  // namespace

namespace rift::test_support {

long allocation_count() {
  return g_count.load();
}

void reset_largest_allocation() {
  g_largest = 0;
}

std::size_t largest_allocation() {
  return g_largest.load();
}

}  // namespace rift::test_support

void* operator new(std::size_t size) {
  g_count.fetch_add(1, std::memory_order_relaxed);
  std::size_t seen = g_largest.load(std::memory_order_relaxed);
  while (size > seen && !g_largest.compare_exchange_weak(seen, size)) {
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
