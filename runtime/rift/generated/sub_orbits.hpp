// The sub-orbits of an orbit, as the folds of generated code walk them
// (`for each <sub>(x) in <o>(d)`, and `OP E over <o>(d)`, which is the fold
// of E over the sub-orbits <e ∩ o>). The darts kept and their order are
// always those of GMap::for_each_sub_orbit (the first dart of each sub-orbit
// in the walk of <o>(d)), so the way chosen never changes a result:
//  - <sub> contains <o>: <o>(d) is one sub-orbit, d stands for it;
//  - <sub> inside <o> and <o> of at most two links: the walk of <o>(d) is a
//    path or a cycle that needs no mark, and a sub-orbit of at most one link
//    is a dart and its neighbour, both in the walk. These walks touch no
//    state of the map, so criteria whose folds are all such collect on
//    every core (lower/criterion_plan.cpp decides it with the same test);
//  - where the map attaches embeddings to <sub>, each sub-orbit has one
//    slot, and the slot tells whether a dart's sub-orbit was met already:
//    only <o>(d) is walked (GMap::for_each_sub_orbit marks the whole
//    sub-orbit of each dart it keeps, so a criterion on vertices folding
//    over each vertex's tetrahedra would walk each tetrahedron's 24 darts
//    once per vertex);
//  - otherwise, or where a dart has no slot, GMap::for_each_sub_orbit.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rift/core/interrupt.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift::generated {

/// Buffers of for_each_sub_orbit, one set per thread: a list of kept darts
/// per nesting level (a fold inside a fold), and one stamp per slot.
struct SubOrbitBuffers {
  std::vector<std::vector<Dart>> kept;
  std::size_t depth = 0;
  std::vector<std::uint32_t> stamp;
  std::uint32_t walk = 0;
};

inline SubOrbitBuffers& sub_orbit_buffers() {
  thread_local SubOrbitBuffers buffers;
  return buffers;
}

/// The map's attachment on orbit `o` when it holds slots, or nullptr.
inline const OrbitAttachment* attachment_on(const GMap& g, Orbit o) {
  for (const auto& a : g.attachments()) {
    if (a->orbit() == o && !a->dormant()) return a.get();
  }
  return nullptr;
}

/// Whether for_each_sub_orbit walks <o> for <sub> without the map's marks
/// (whatever the map attaches), hence safely on several threads at once.
constexpr bool walks_without_marks(Orbit o, Orbit sub) {
  const auto both = static_cast<std::uint8_t>(o.mask() & sub.mask());
  return both == o.mask() || (both == sub.mask() && o.size() <= 2);
}

namespace detail {

/// One nesting level of kept darts, released even when f throws (an interrupt).
class KeptLevel {
 public:
  explicit KeptLevel(SubOrbitBuffers& b) : b_(b), at_(b.depth++) {
    if (b_.kept.size() <= at_) b_.kept.resize(at_ + 1);
    b_.kept[at_].clear();
  }
  ~KeptLevel() { --b_.depth; }
  KeptLevel(const KeptLevel&) = delete;
  KeptLevel& operator=(const KeptLevel&) = delete;
  // By index: a nested walk may grow b.kept and move this level's list.
  std::vector<Dart>& darts() { return b_.kept[at_]; }

 private:
  SubOrbitBuffers& b_;
  std::size_t at_;
};

}  // namespace detail

/// Calls f(x) with one dart x of each distinct sub-orbit <sub>(x) inside
/// <o>(d): the darts of GMap::for_each_sub_orbit, in its order. A walk that
/// keeps darts in the buffers finishes before any f, so that f's own walks
/// (a fold inside a fold) reuse the buffers freely.
template <class F>
void for_each_sub_orbit(const GMap& g, Dart d, Orbit o, Orbit sub, F&& f) {
  const auto both = static_cast<std::uint8_t>(o.mask() & sub.mask());
  if (both == o.mask()) {
    f(d);
    return;
  }
  if (both == sub.mask() && o.size() <= 2) {
    // Streamed: f runs during the walk, which needs no buffer and no mark
    // (these folds are the hot ones: the atomic criteria sum stored forces
    // over each edge end's <1>, 2 darts, every step).
    if (o.size() == 1) {  // <sub> is <>: d and its neighbour
      const Dart e = g.alpha(d, o.first());
      f(d);
      if (e != d) f(e);
      return;
    }
    // A sub-orbit <k> is a dart and its neighbour by k. The walk meets the
    // two one after the other, so the second is the one reached through k,
    // except d's neighbour, met last (the end of a cycle or of a path's
    // second leg), which d stands for.
    const int k = sub.size() == 0 ? -1 : sub.first();
    g.for_each_in_two_link_orbit(d, o.first(), o.second(), [&](Dart x, int via) {
      throw_if_interrupted();  // a polygon's face may have a million darts
      if (k >= 0 && x != d && (via == k || g.alpha(x, k) == d)) return;
      f(x);
    });
    return;
  }
  SubOrbitBuffers& b = sub_orbit_buffers();
  const OrbitAttachment* slots = attachment_on(g, sub);
  if (!slots) {
    g.for_each_sub_orbit(d, o, sub, f);
    return;
  }
  detail::KeptLevel level(b);
  if (b.stamp.size() < slots->slot_capacity()) b.stamp.resize(slots->slot_capacity(), 0);
  if (++b.walk == 0) {  // the numbers wrapped: no stale stamp may match
    std::fill(b.stamp.begin(), b.stamp.end(), 0);
    b.walk = 1;
  }
  bool slotless = false;
  const std::uint32_t walk = b.walk;
  g.for_each_in_orbit(d, o, [&](Dart x) {
    const Slot s = slots->slot(x);
    if (s == kNoSlot) {
      slotless = true;
      return;
    }
    if (b.stamp[s] == walk) return;
    b.stamp[s] = walk;
    level.darts().push_back(x);
  });
  if (slotless) {
    g.for_each_sub_orbit(d, o, sub, f);
    return;
  }
  for (std::size_t k = 0; k < level.darts().size(); ++k)
    f(level.darts()[k]);
}

}  // namespace rift::generated
