// Large flat arrays (embedding columns, dart links, slot indices) backed by
// transparent huge pages where the system allows it.
//
// The columns of a 10^6-vertex mesh take hundreds of MB. Filled for the first
// time page by page, they cost one page fault per 4 KiB, and those faults
// dominated the set-up of large meshes (issue 12). A huge page is faulted in
// once per 2 MiB. The kernel only gives huge pages to memory advised before
// its first touch (transparent_hugepage=madvise, Debian's default), hence
// the helper that grows a vector into a fresh, advised buffer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace rift {

/// Arrays smaller than this are left alone (a huge page is 2 MiB).
inline constexpr std::size_t kHugePageAdviceBytes = std::size_t{4} << 20;

/// Asks the kernel to back the 2 MiB-aligned part of [data, data + bytes)
/// with transparent huge pages. Only a hint: does nothing where unsupported.
void advise_huge_pages(const void* data, std::size_t bytes);

/// v.reserve(n), except that a large array gets a fresh buffer advised for
/// huge pages (its elements move there): for arrays filled by push_back up to
/// a known bound, which then neither move nor fault in 4 KiB at a time. Only
/// the pages written become resident, so a generous bound costs address
/// space, not memory.
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  if (n * sizeof(T) < kHugePageAdviceBytes) {
    v.reserve(n);
    return;
  }
  std::vector<T, A> bigger;
  bigger.reserve(n);
  advise_huge_pages(bigger.data(), bigger.capacity() * sizeof(T));
  bigger.insert(bigger.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(bigger);
}

/// v.resize(n, fill), except that a large array that must move to a new
/// buffer gets one advised for huge pages before anything is written to it.
/// The capacity grows geometrically, as resize's would.
template <class T, class A>
void grow_huge(std::vector<T, A>& v, std::size_t n, const T& fill) {
  if (n > v.capacity() && n * sizeof(T) >= kHugePageAdviceBytes) {
    std::vector<T, A> bigger;
    bigger.reserve(std::max(n, 2 * v.capacity()));
    advise_huge_pages(bigger.data(), bigger.capacity() * sizeof(T));
    bigger.insert(bigger.end(), std::make_move_iterator(v.begin()),
                  std::make_move_iterator(v.end()));
    v.swap(bigger);
  }
  v.resize(n, fill);
}

/// Empties v and gives its buffer back. (`v = {}` would not: it assigns an
/// empty initializer list, which keeps the capacity.)
template <class T, class A>
void give_back(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace rift
