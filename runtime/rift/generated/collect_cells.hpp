// How a criterion's collect() visits its cells (riftc emits one call per
// criterion): over the map's cells listed once per topology (CellList), on
// one thread or in fixed blocks spread over every core. Each block appends
// its candidates to a list of its own, and the lists are joined in block
// order: the candidates come out in the order of the cells, as a single
// thread gives them, whatever the number of threads (the tear order, and so
// the simulation, must not depend on it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rift/core/parallel.hpp"
#include "rift/gmap/cell_list.hpp"
#include "rift/gmap/gmap.hpp"
#include "rift/sim/criterion.hpp"

namespace rift::generated {

enum class CollectOn { kOneThread, kEveryCore };

/// What one criterion keeps between collections: its cells and one candidate
/// list per block (grown, never shrunk: a warm collection allocates nothing).
class CellCollection {
 public:
  /// visit(d, found) for every cell <o>(d) of g, where visit appends the
  /// cell's candidates to `found`; they reach `out` in the order of the cells.
  /// kOnEveryCore: visit may run for several cells at once, so it must not
  /// touch state shared between cells (riftc checks that it does not).
  template <class F>
  void collect(const GMap& g, Orbit o, CollectOn on, std::vector<TearCandidate>& out, F&& visit) {
    const std::vector<Dart>& cells = cells_.of(g, o);
    if (on == CollectOn::kOneThread) {
      for (const Dart d : cells)
        visit(d, out);
      return;
    }
    const std::size_t blocks = (cells.size() + kParallelBlock - 1) / kParallelBlock;
    if (found_.size() < blocks) found_.resize(blocks);
    auto run = [&](std::size_t first, std::size_t last) {
      std::vector<TearCandidate>& found = found_[first / kParallelBlock];
      found.clear();
      for (std::size_t i = first; i < last; ++i)
        visit(cells[i], found);
    };
    parallel_blocks(cells.size(), kParallelBlock, run);
    for (std::size_t b = 0; b < blocks; ++b)
      out.insert(out.end(), found_[b].begin(), found_[b].end());
  }

  /// Rewrites touched these darts since topology version `from` (CellList::note_changed).
  void note_changed(const GMap& g, std::span<const Dart> touched, std::uint64_t from) {
    cells_.note_changed(g, touched, from);
  }

  /// The cell list, for tests.
  const CellList& cells() const { return cells_; }

 private:
  CellList cells_;
  std::vector<std::vector<TearCandidate>> found_;
};

}  // namespace rift::generated
