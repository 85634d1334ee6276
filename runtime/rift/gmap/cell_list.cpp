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
// darts are walked (marked) for their smallest darts; the old cells that died
// or lie in a walked orbit are dropped; the smallest darts walked come in,
// in order. One pass over the list, merging: the criterion's evaluation
// passes over every cell anyway.
void CellList::apply_pending(const GMap& g) {
  const Mark m = g.reserve_mark();
  walked_.clear();
  smallest_.clear();
  for (const Dart t : pending_) {
    if (t >= g.capacity() || !g.is_alive(t) || g.is_marked(t, m)) continue;
    Dart smallest = t;
    g.for_each_in_orbit(t, orbit_, [&](Dart x) {
      g.mark(x, m);
      walked_.push_back(x);
      smallest = std::min(smallest, x);
    });
    smallest_.push_back(smallest);
  }
  std::sort(smallest_.begin(), smallest_.end());
  merged_.clear();
  merged_.reserve(cells_.size() + smallest_.size());
  auto fresh = smallest_.begin();
  for (const Dart c : cells_) {
    if (!g.is_alive(c) || g.is_marked(c, m)) continue;
    while (fresh != smallest_.end() && *fresh < c)
      merged_.push_back(*fresh++);
    merged_.push_back(c);
  }
  merged_.insert(merged_.end(), fresh, smallest_.end());
  cells_.swap(merged_);
  for (const Dart x : walked_)
    g.unmark(x, m);
  g.free_mark(m);
  pending_.clear();
  ++updates_;
}

}  // namespace rift
