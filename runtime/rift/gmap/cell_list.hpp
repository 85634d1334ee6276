// The cells <o> of a map as GMap::for_each_cell visits them (the smallest
// dart of each orbit, in increasing order), kept between calls and rebuilt
// only when the map's links changed (GMap::topology_version): a criterion
// evaluated every step pays the orbit marking of for_each_cell only on the
// steps after a tear, and its cells can be cut into blocks for the threads
// (rift/generated/collect_cells.hpp), which marking, a shared state of the
// map, does not allow.
//
// A CellList serves one orbit type; it follows whichever map it is given
// (GMap::identity tells maps apart).
#pragma once

#include <cstdint>
#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift {

class CellList {
 public:
  /// One dart per orbit <o> of g, the one for_each_cell(o) would give, in the same order.
  const std::vector<Dart>& of(const GMap& g, Orbit o) {
    if (!built_ || identity_ != g.identity() || version_ != g.topology_version() || orbit_ != o) {
      cells_.clear();
      g.for_each_cell(o, [&](Dart d) { cells_.push_back(d); });
      identity_ = g.identity();
      version_ = g.topology_version();
      orbit_ = o;
      built_ = true;
      ++rebuilds_;
    }
    return cells_;
  }
  /// How many times the list was built (tests check that a quiet step reuses it).
  std::uint64_t rebuilds() const { return rebuilds_; }

 private:
  std::vector<Dart> cells_;
  std::uint64_t identity_ = 0;
  std::uint64_t version_ = 0;
  Orbit orbit_;
  bool built_ = false;
  std::uint64_t rebuilds_ = 0;
};

}  // namespace rift
