// How a criterion's collect() visits its cells (riftc emits one call per
// criterion): over the map's cells listed once per topology (CellList), on
// one thread or in fixed blocks spread over every core. Each block appends
// its candidates to a list of its own, and the lists are joined in block
// order: the candidates come out in the order of the cells, as a single
// thread gives them, whatever the number of threads (the tear order, and so
// the simulation, must not depend on it).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rift/core/interrupt.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/parallel.hpp"
#include "rift/gmap/cell_list.hpp"
#include "rift/gmap/gmap.hpp"
#include "rift/sim/criterion.hpp"

// On the lambda riftc emits for a cell's body, called once per cell of a
// block: inlined into the block's loop, so that the block's locals (the
// embeddings' arrays) stay in registers across its cells.
#if defined(__GNUC__) || defined(__clang__)
#define RIFT_CELL_BODY __attribute__((always_inline))
#else
#define RIFT_CELL_BODY
#endif

namespace rift::generated {

enum class CollectOn { kOneThread, kEveryCore };

/// What one criterion keeps between collections: its cells and one candidate
/// list per block (grown, never shrunk: a warm collection allocates nothing).
class CellCollection {
 public:
  /// visit_block(cells, found) for consecutive blocks of the cells <o>(d) of
  /// g, where visit_block appends the candidates of the cells of its span to
  /// `found`; they reach `out` in the order of the cells.
  ///
  /// A block, not a cell, per call: riftc's visit takes what the cells read
  /// (the embeddings' arrays) into locals once per block and loops over the
  /// cells itself, so that those stay in registers across cells instead of
  /// being loaded again through a closure, with a call, at every cell (a
  /// fifth of the instructions of the atomic edge criterion). The interrupt
  /// is polled before each block.
  /// kOnEveryCore: blocks may run at once, so visit_block must not touch
  /// state shared between cells (riftc checks that it does not).
  template <class F>
  void collect(const GMap& g, Orbit o, CollectOn on, std::vector<TearCandidate>& out,
               F&& visit_block) {
    const std::vector<Dart>& cells = cells_.of(g, o);
    const std::span<const Dart> all(cells);
    if (on == CollectOn::kOneThread) {
      for (std::size_t first = 0; first < all.size(); first += kParallelBlock) {
        throw_if_interrupted();
        visit_block(all.subspan(first, std::min(kParallelBlock, all.size() - first)), out);
      }
      return;
    }
    const std::size_t blocks = (cells.size() + kParallelBlock - 1) / kParallelBlock;
    if (found_.size() < blocks) found_.resize(blocks);
    auto run = [&](std::size_t first, std::size_t last) {
      std::vector<TearCandidate>& found = found_[first / kParallelBlock];
      found.clear();
      throw_if_interrupted();
      visit_block(all.subspan(first, last - first), found);
    };
    parallel_blocks(cells.size(), kParallelBlock, run);
    for (std::size_t b = 0; b < blocks; ++b)
      out.insert(out.end(), found_[b].begin(), found_[b].end());
  }

  /// Rewrites touched these darts since topology version `from` (CellList::note_changed).
  void note_changed(const GMap& g, std::span<const Dart> touched, std::uint64_t from) {
    cells_.note_changed(g, touched, from);
  }

  /// Its cells and candidate lists, under `owner` (MemoryReport).
  void report_memory(MemoryReport& report, std::string_view owner) const {
    report.add(owner, "cells", cells_.list_bytes());
    report.add(owner, "cell list upkeep", cells_.upkeep_bytes());
    std::size_t found = 0;
    for (const auto& list : found_)
      found += list.capacity() * sizeof(TearCandidate);
    report.add(owner, "candidate lists", found);
  }

  /// The cell list, for tests.
  const CellList& cells() const { return cells_; }

 private:
  CellList cells_;
  std::vector<std::vector<TearCandidate>> found_;
};

}  // namespace rift::generated
