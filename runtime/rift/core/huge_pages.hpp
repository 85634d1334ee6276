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

/// Arrays smaller than this are not populated ahead (populate_for_write):
/// too few huge pages to share among threads.
inline constexpr std::size_t kPopulateMinBytes = std::size_t{16} << 20;

/// Faults in the pages of [data, data + bytes), about to be written for the
/// first time, on every thread of the parallel passes (rift/core/parallel.hpp)
/// without writing them (MADV_POPULATE_WRITE). The kernel clears each new
/// page on the thread that faults it: a 10^6-vertex hexahedral block's set-up
/// spent a fifth to a half of its time clearing pages on one core (issue 12),
/// and the host of a virtual machine backs fresh memory at a fault's cost
/// too. Only the speed of the write that follows changes. Does nothing on
/// one thread, below kPopulateMinBytes or where the kernel lacks the advice
/// (before Linux 5.14).
void populate_for_write(const void* data, std::size_t bytes);

/// Growth headroom (issue 12, a tear costs what it touches). A large array
/// (headroom_min_bytes() or more) that reserve_huge or grow_huge gives a new
/// buffer gets capacity for headroom_factor() times the elements asked for:
/// address space, not memory, since only the pages written become resident.
/// A rewrite that adds a few darts, slots or matches to a 10^6-vertex map
/// then appends in place instead of copying (and faulting in) every dart
/// array and column of the map at its first tear. Past the headroom an array
/// grows again by the same factor (and at least doubles), so growth stays
/// amortised. Default 2 (the next doubling reserved ahead); 1 gives exact
/// buffers, as without headroom. A small array gets exactly what it asks for
/// (copying it is cheap, and its spare room would be memory: malloc's heap).
std::size_t headroom_factor();
/// The size from which an array gets headroom (default kHugePageAdviceBytes).
std::size_t headroom_min_bytes();
/// Sets both for arrays given a buffer from now on (tests compare small maps
/// that outgrow their headroom with maps that never do).
void set_headroom_factor(std::size_t factor, std::size_t min_bytes = kHugePageAdviceBytes);

namespace detail {
/// Moves v's elements to a fresh buffer of headroom_factor() * n elements,
/// and at least twice the old capacity (amortised growth whatever the factor).
/// Only the first n elements' pages are advised for huge pages: the headroom
/// stays in 4 KiB pages, so that the last huge page of the used part, and
/// nothing past it, becomes resident (peak memory as without headroom).
/// Whether an array of n elements is large enough for headroom.
template <class T>
bool gets_headroom(std::size_t n) {
  return n * sizeof(T) >= headroom_min_bytes();
}

/// `written` (at most n): the elements the caller writes at once, whose
/// pages are populated on every thread (populate_for_write).
template <class T, class A>
void regrow_huge(std::vector<T, A>& v, std::size_t n, std::size_t written = 0) {
  std::vector<T, A> bigger;
  bigger.reserve(std::max(n * headroom_factor(), 2 * v.capacity()));
  if (n * sizeof(T) >= kHugePageAdviceBytes) advise_huge_pages(bigger.data(), n * sizeof(T));
  populate_for_write(bigger.data(), written * sizeof(T));
  bigger.insert(bigger.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(bigger);
}
}  // namespace detail

/// v.reserve(n) with headroom (see headroom_factor), the part for n elements
/// of a large array advised for huge pages: for arrays filled by push_back up
/// to a known bound, which then neither move nor fault in 4 KiB at a time.
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  if (!detail::gets_headroom<T>(n)) {
    v.reserve(n);
    return;
  }
  detail::regrow_huge(v, n);
}

/// v.resize(n, fill), except that an array that must move to a new buffer
/// gets one with headroom (see headroom_factor), advised for huge pages
/// before anything is written to it when large, and that the pages the
/// resize writes are faulted in on every thread first (populate_for_write).
template <class T, class A>
void grow_huge(std::vector<T, A>& v, std::size_t n, const T& fill) {
  if (n > v.capacity() && detail::gets_headroom<T>(n)) {
    detail::regrow_huge(v, std::max(n, v.size() + 1), n);
  } else if (n > v.size() && n <= v.capacity()) {
    // Within the buffer's headroom: the new elements' pages may be fresh.
    populate_for_write(v.data() + v.size(), (n - v.size()) * sizeof(T));
  }
  v.resize(n, fill);
}

/// v.push_back(x), growing like grow_huge when v is full.
template <class T, class A>
void push_back_huge(std::vector<T, A>& v, const T& x) {
  if (v.size() == v.capacity() && detail::gets_headroom<T>(v.size() + 1))
    detail::regrow_huge(v, v.size() + 1);
  v.push_back(x);
}

/// Gives v, filled to its size piece by piece (its last regrow may have left
/// it nearly full), the headroom a regrow would give it now, so that the
/// rewrites that extend it later append in place instead of one of them
/// copying the whole array (a large array only, as grow_huge).
template <class T, class A>
void reserve_headroom(std::vector<T, A>& v) {
  if (detail::gets_headroom<T>(v.size()) && v.capacity() < v.size() * headroom_factor())
    detail::regrow_huge(v, v.size());
}

/// Empties v and gives its buffer back. (`v = {}` would not: it assigns an
/// empty initializer list, which keeps the capacity.)
template <class T, class A>
void give_back(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace rift
