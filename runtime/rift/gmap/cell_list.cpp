#include "rift/gmap/cell_list.hpp"

#include <algorithm>

namespace rift {

const std::vector<Dart>& CellList::of(const GMap& g, Orbit o) {
  if (!built_ || identity_ != g.identity() || version_ != g.topology_version() || orbit_ != o) {
    rebuild(g, o);
  } else if (!pending_.empty()) {
    apply_pending(g);
  }
  return cells_;
}

void CellList::note_changed(const GMap& g, std::span<const Dart> touched, std::uint64_t from) {
  if (!built_ || identity_ != g.identity()) return;  // built anew at the next of() anyway
  if (version_ != from) {
    built_ = false;  // changes it was not told of
    pending_.clear();
    return;
  }
  // Past this many touched darts (a list whose criterion is not collected
  // between tears), walking their orbits would cost more than building anew.
  if (pending_.size() + touched.size() > pending_limit()) {
    built_ = false;
    pending_.clear();
    return;
  }
  pending_.insert(pending_.end(), touched.begin(), touched.end());  // within its reserve
  version_ = g.topology_version();
}

void CellList::rebuild(const GMap& g, Orbit o) {
  cells_.clear();
  g.for_each_cell(o, [&](Dart d) { cells_.push_back(d); });
  identity_ = g.identity();
  version_ = g.topology_version();
  orbit_ = o;
  built_ = true;
  pending_.clear();
  // Tears then note their darts without allocating (NoAllocation.*).
  pending_.reserve(pending_limit());
  ++rebuilds_;
}

// Every orbit that changed holds a live touched dart (a rewrite relinks,
// creates or deletes only touched darts), and an orbit that holds none is as
// it was, its smallest dart with it. So: the orbits of the live touched
// darts are walked for their smallest darts; the old cells that died (touched
// darts) or lie in a walked orbit are dropped, found by binary search; the
// smallest darts walked come in, in order. The list is copied once, in runs
// between those few edits (a memcpy: 2 ms for the 4·10^6 edges of a
// 10^6-vertex cloth, where listing them anew took 9 ms and a marked walk of
// its edge pairs 26 ms).
void CellList::apply_pending(const GMap& g) {
  const Mark m = g.reserve_mark();
  walked_.clear();
  smallest_.clear();
  for (const Dart t : pending_) {
    if (t >= g.capacity() || !g.is_alive(t)) {
      walked_.push_back(t);  // dead: a cell it was is dropped
      continue;
    }
    if (g.is_marked(t, m)) continue;
    Dart smallest = t;
    g.for_each_in_orbit(t, orbit_, [&](Dart x) {
      g.mark(x, m);
      walked_.push_back(x);
      smallest = std::min(smallest, x);
    });
    smallest_.push_back(smallest);
  }
  for (const Dart x : walked_) {
    if (x < g.capacity() && g.is_alive(x)) g.unmark(x, m);
  }
  g.free_mark(m);
  std::sort(smallest_.begin(), smallest_.end());
  // The positions of the dropped cells, in increasing order. Each walked
  // orbit holds at most one old cell, so few of the walked darts are found:
  // only those positions are sorted (a dead dart noted twice gives one twice).
  dropped_.clear();
  for (const Dart x : walked_) {
    const auto it = std::lower_bound(cells_.begin(), cells_.end(), x);
    if (it != cells_.end() && *it == x)
      dropped_.push_back(static_cast<std::size_t>(it - cells_.begin()));
  }
  std::sort(dropped_.begin(), dropped_.end());
  dropped_.erase(std::unique(dropped_.begin(), dropped_.end()), dropped_.end());
  merged_.clear();
  merged_.reserve(cells_.size() - dropped_.size() + smallest_.size());
  auto fresh = smallest_.begin();
  // Copies cells_[first, last) (kept cells), the fresh darts that fall among them in place.
  auto copy_run = [&](std::size_t first, std::size_t last) {
    while (first < last) {
      if (fresh == smallest_.end() || *fresh > cells_[last - 1]) {
        merged_.insert(merged_.end(), cells_.begin() + static_cast<std::ptrdiff_t>(first),
                       cells_.begin() + static_cast<std::ptrdiff_t>(last));
        return;
      }
      const auto at = std::lower_bound(cells_.begin() + static_cast<std::ptrdiff_t>(first),
                                       cells_.begin() + static_cast<std::ptrdiff_t>(last), *fresh);
      merged_.insert(merged_.end(), cells_.begin() + static_cast<std::ptrdiff_t>(first), at);
      merged_.push_back(*fresh++);
      first = static_cast<std::size_t>(at - cells_.begin());
    }
  };
  std::size_t kept_from = 0;
  for (const std::size_t p : dropped_) {
    copy_run(kept_from, p);
    kept_from = p + 1;
  }
  copy_run(kept_from, cells_.size());
  merged_.insert(merged_.end(), fresh, smallest_.end());
  cells_.swap(merged_);
  pending_.clear();
  ++updates_;
}

}  // namespace rift
