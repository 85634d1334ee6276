// The cells <o> of a map as GMap::for_each_cell visits them (the smallest
// dart of each orbit, in increasing order), kept between calls: a criterion
// evaluated every step pays the orbit marking of for_each_cell only once, and
// its cells can be cut into blocks for the threads
// (rift/generated/collect_cells.hpp), which marking, a shared state of the
// map, does not allow.
//
// After a rewrite the list is not built again: whoever rewrote the map tells
// it which darts the rewrites touched (note_changed, called by
// Simulation::on_topology_changed through Criterion::topology_changed), and
// the next of() walks only the orbits of those darts. Building the list of a
// 10^6-vertex block's faces anew took 0.8 s, paid at every step that tore
// (issue 12: a tear costs what it touches). A change the list was not told of
// (the map's topology_version() moved past what it knows) makes it build the
// list anew, as before.
//
// A CellList serves one orbit type; it follows whichever map it is given
// (GMap::identity tells maps apart).
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "rift/gmap/gmap.hpp"

namespace rift {

class CellList {
 public:
  /// One dart per orbit <o> of g, the one for_each_cell(o) would give, in the same order.
  const std::vector<Dart>& of(const GMap& g, Orbit o);

  /// Tells the list that rewrites took g from topology version `from` to its
  /// current one, touching (creating, deleting or relinking) exactly the
  /// darts of `touched` (and no others). The list follows them at the next
  /// of(); a list that does not know version `from` is built anew then.
  void note_changed(const GMap& g, std::span<const Dart> touched, std::uint64_t from);

  /// How many times the list was built from the whole map (tests check that
  /// a quiet step reuses it, and that a tear does not build it anew).
  std::uint64_t rebuilds() const { return rebuilds_; }
  /// How many times it followed noted changes instead.
  std::uint64_t updates() const { return updates_; }
  /// Bytes of the list itself.
  std::size_t list_bytes() const { return cells_.size() * sizeof(Dart); }
  /// Bytes of what following changes keeps: the pending darts and the scratch.
  std::size_t upkeep_bytes() const {
    const std::size_t darts =
        pending_.size() + walked_.capacity() + smallest_.capacity() + merged_.capacity();
    return darts * sizeof(Dart) + dropped_.capacity() * sizeof(std::size_t);
  }

 private:
  void rebuild(const GMap& g, Orbit o);
  std::size_t pending_limit() const { return std::max<std::size_t>(cells_.size() / 4, 4096); }
  void apply_pending(const GMap& g);

  std::vector<Dart> cells_;
  std::uint64_t identity_ = 0;
  std::uint64_t version_ = 0;  // the version cells_ and pending_ together describe
  Orbit orbit_;
  bool built_ = false;
  std::uint64_t rebuilds_ = 0;
  std::uint64_t updates_ = 0;
  std::vector<Dart> pending_;  // darts touched since cells_ was last brought up to date
  // apply_pending's scratch, kept so that an update allocates nothing once warm.
  std::vector<Dart> walked_, smallest_, merged_;
  std::vector<std::size_t> dropped_;
};

}  // namespace rift
