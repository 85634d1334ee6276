// Sums per-element contributions ("terms") into per-vertex totals on every
// core, in an order that does not depend on the thread count.
//
// A force pass or a matrix product scatters: each element adds a term to each
// of its vertices, and two elements sharing a vertex would race on it. Here
// the elements write their terms into their own entries of a flat array (in
// parallel, no conflict), and a second, per-vertex pass adds to each vertex
// its terms in increasing entry order: the order in which a one-thread
// scatter over the same entries adds them, so the sums are bit for bit those
// of the sequential loop, whatever the threads.
//
// The entry-to-vertex map is a CSR built by a counting sort from the targets
// (the element's vertex slots in entry order), once per change of the
// elements (a tear), not per pass.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rift/core/parallel.hpp"
#include "rift/core/types.hpp"

namespace rift {

class TermGather {
 public:
  /// Term t goes to vertex slot targets[t] (kNoSlot: nowhere). O(terms +
  /// slots); reuses its arrays, so rebuilding to a size seen before
  /// allocates nothing.
  void build(std::span<const Slot> targets);

  /// out[s] += terms[t] for every t with targets[t] == s, t increasing, in
  /// parallel over the slots. `terms` is in the entry order of build().
  void add_to(const Vec3* terms, Vec3* out) const;

  /// out[s] += term(t) for every t with targets[t] == s, t increasing, in
  /// parallel over the slots: for terms that are not a flat array of their
  /// own (the diagonal blocks of element matrices, read in place).
  template <class T, class Term>
  void add_each(T* out, Term&& term) const {
    parallel_for(slots(), [&](std::size_t s) {
      const std::uint32_t end = offsets_[s + 1];
      std::uint32_t k = offsets_[s];
      if (k == end) return;
      T sum = out[s];
      for (; k < end; ++k)
        sum += term(entries_[k]);
      out[s] = sum;
    });
  }

  /// Bytes of its offsets and entries.
  std::size_t bytes() const { return (offsets_.size() + entries_.size()) * sizeof(std::uint32_t); }

  /// Slots that receive a term: max target + 1.
  std::size_t slots() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }

 private:
  std::vector<std::uint32_t> offsets_;  ///< slots() + 1: where each slot's entries start
  std::vector<std::uint32_t> entries_;  ///< term indices, by slot, increasing within a slot
};

}  // namespace rift
