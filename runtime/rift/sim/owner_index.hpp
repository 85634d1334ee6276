// Which entry of a MatchCache each owner dart holds, for re-matching after a
// rewrite (match_cache.hpp).
//
// Most interactions own a match on a large share of the darts (a stretch
// spring on every other dart), and a plain array indexed by dart, 4 bytes a
// dart, is the cheapest index. An interaction of a few darts per element owns
// far fewer: a hexahedron's volume shear one match per 48 darts, a
// tetrahedron's co-rotational element one per 24. Its array would be 4 bytes
// a dart all the same (178 MB of a 4.7·10⁷-dart hexahedral block for 10⁶
// matches, issue 12's lean memory), so such an index is a hash table of its
// owners instead: open addressing with linear probing, at most half full, 8
// bytes a slot, so between 16 and 32 bytes per match.
//
// The kind is chosen at build, the smaller of the two for the owners and
// darts at hand, and kept afterwards; both give the same entries, so nothing but memory and
// the cost of a lookup depends on it.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "rift/core/huge_pages.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/prefetch.hpp"
#include "rift/core/types.hpp"

namespace rift {

class OwnerIndex {
  struct Cell {
    Dart owner = kNoDart;
    std::uint32_t entry = ~0u;
  };

 public:
  static constexpr std::uint32_t kNone = ~0u;

  /// Whether a hash table of `owners` owners is smaller than an array for
  /// `darts` darts (16–32 bytes an owner against 4 bytes a dart).
  static bool hashes(std::size_t owners, std::size_t darts) {
    return table_size_for(owners) * sizeof(Cell) < darts * sizeof(std::uint32_t);
  }

  /// Indexes owners[e] -> e for a map of `darts` darts, as an array or a
  /// hash table, whichever is smaller (hashes); `sparse` forces the kind
  /// (tests).
  void build(std::span<const Dart> owners, std::size_t darts) {
    build(owners, darts, hashes(owners.size(), darts));
  }
  void build(std::span<const Dart> owners, std::size_t darts, bool sparse) {
    clear();
    sparse_ = sparse;
    if (sparse_) {
      rehash(table_size_for(owners.size()));
    } else {
      grow_huge(entry_of_dart_, darts, kNone);
    }
    // A large table's homes are far from the caches and hashed apart: each
    // owner's home is asked for kAhead owners before it is filled, so the
    // misses overlap (the shear springs' 5.8·10^6 owners of a 10^6-vertex
    // hexahedral block missed one after the other). The table is sized for
    // them all (table_size_for), so no rehash moves it in between.
    constexpr std::size_t kAhead = 16;
    const std::size_t n = owners.size();
    for (std::size_t e = 0; e < n; ++e) {
      if (sparse_ && e + kAhead < n) prefetch(&table_[home(owners[e + kAhead])]);
      set(owners[e], static_cast<std::uint32_t>(e));
    }
  }

  /// Gives the memory back; the index is then empty (find gives kNone).
  void clear() {
    give_back(entry_of_dart_);
    give_back(table_);
    used_ = 0;
    sparse_ = false;
  }

  bool sparse() const { return sparse_; }
  /// Owners indexed.
  std::size_t size() const {
    if (sparse_) return used_;
    return static_cast<std::size_t>(std::count_if(entry_of_dart_.begin(), entry_of_dart_.end(),
                                                  [](std::uint32_t e) { return e != kNone; }));
  }

  /// A map grown to `darts` darts: the array covers them (the table needs nothing).
  void cover(std::size_t darts) {
    if (!sparse_ && entry_of_dart_.size() < darts) grow_huge(entry_of_dart_, darts, kNone);
  }

  /// The entry d owns, or kNone.
  std::uint32_t find(Dart d) const {
    if (!sparse_) return d < entry_of_dart_.size() ? entry_of_dart_[d] : kNone;
    if (table_.empty()) return kNone;
    for (std::size_t i = home(d);; i = (i + 1) & mask()) {
      const Cell& c = table_[i];
      if (c.owner == d) return c.entry;
      if (c.owner == kNoDart) return kNone;
    }
  }

  /// d now owns entry e (d may own one already: it is replaced).
  void set(Dart d, std::uint32_t e) {
    if (!sparse_) {
      if (entry_of_dart_.size() <= d) grow_huge(entry_of_dart_, std::size_t{d} + 1, kNone);
      entry_of_dart_[d] = e;
      return;
    }
    if (2 * (used_ + 1) > table_.size()) rehash(table_size_for(used_ + 1));
    std::size_t i = home(d);
    for (; table_[i].owner != kNoDart; i = (i + 1) & mask()) {
      if (table_[i].owner == d) {
        table_[i].entry = e;
        return;
      }
    }
    table_[i] = {d, e};
    ++used_;
  }

  /// d owns nothing any more.
  void erase(Dart d) {
    if (!sparse_) {
      if (d < entry_of_dart_.size()) entry_of_dart_[d] = kNone;
      return;
    }
    if (table_.empty()) return;
    std::size_t hole = home(d);
    while (table_[hole].owner != d) {
      if (table_[hole].owner == kNoDart) return;
      hole = (hole + 1) & mask();
    }
    // Backward shift: the cells after the hole that probed past it move
    // into it, so that every lookup still meets its owner before an empty cell.
    for (std::size_t next = (hole + 1) & mask(); table_[next].owner != kNoDart;
         next = (next + 1) & mask()) {
      const std::size_t h = home(table_[next].owner);
      // The cell at `next` may fill the hole unless its home lies strictly
      // between the hole and it (cyclically).
      const bool stays = hole <= next ? (hole < h && h <= next) : (hole < h || h <= next);
      if (stays) continue;
      table_[hole] = table_[next];
      hole = next;
    }
    table_[hole] = {kNoDart, kNone};
    --used_;
  }

  /// A hint that find(d) comes soon.
  void prefetch_owner(Dart d) const {
    if (!sparse_) {
      if (d < entry_of_dart_.size()) prefetch(&entry_of_dart_[d]);
    } else if (!table_.empty()) {
      prefetch(&table_[home(d)]);
    }
  }

  void report_memory(MemoryReport& report, std::string_view owner) const {
    report.add(owner, "entry of each dart", entry_of_dart_);
    report.add(owner, "entries of the owners (hash table)", table_);
  }

 private:
  /// At least two runs of cells (home keeps bits_ - kRunBits >= 1).
  static std::size_t table_size_for(std::size_t owners) {
    return std::bit_ceil(std::max<std::size_t>(2 * owners, 16));
  }
  std::size_t mask() const { return table_.size() - 1; }
  /// Darts in runs of 2^kRunBits consecutive indices keep their run's cells
  /// together: a run's place in the table is hashed, a dart's offset in its
  /// run kept. A tear re-matches the darts of a few faces, created together
  /// and so mostly consecutive; with each dart hashed on its own, every
  /// lookup of a 10^6-vertex cloth's tear missed the cache (a tenth of the
  /// tear's time), where a run's lookups now share one line of 8 cells.
  static constexpr int kRunBits = 3;
  /// Fibonacci hashing of the run: consecutive runs (the owners of a build)
  /// land far apart, and the top bits are the ones kept.
  std::size_t home(Dart d) const {
    const std::uint64_t h = std::uint64_t{d >> kRunBits} * 0x9E3779B97F4A7C15ull;
    const std::size_t run = static_cast<std::size_t>(h >> (64 - (bits_ - kRunBits)));
    return run << kRunBits | (d & ((Dart{1} << kRunBits) - 1));
  }
  void rehash(std::size_t size) {
    std::vector<Cell> old;
    old.swap(table_);
    grow_huge(table_, size, Cell{});
    bits_ = std::countr_zero(size);
    used_ = 0;
    for (const Cell& c : old) {
      if (c.owner != kNoDart) set(c.owner, c.entry);
    }
  }

  bool sparse_ = false;
  std::vector<std::uint32_t> entry_of_dart_;  ///< dense: indexed by dart
  std::vector<Cell> table_;                   ///< sparse: size a power of two
  int bits_ = 0;
  std::size_t used_ = 0;
};

}  // namespace rift
