// The sub-orbits of an orbit, as the folds of generated code walk them
// (`for each <sub>(x) in <o>(d)`): GMap::for_each_sub_orbit marks the whole
// sub-orbit of each dart it keeps, so a criterion on vertices that folds over
// each vertex's tetrahedra walks every tetrahedron's 24 darts once per vertex.
// Where the map attaches embeddings to <sub>, each sub-orbit has one slot,
// and the slot tells whether a dart's sub-orbit was met already: only <o>(d)
// is walked. The darts kept and their order are those of
// GMap::for_each_sub_orbit (the first dart of each sub-orbit in the walk of
// <o>(d)), so results do not change; a dart without a slot falls back to it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

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

/// The map's attachment on orbit `o`, or nullptr.
inline const OrbitAttachment* attachment_on(const GMap& g, Orbit o) {
  for (const auto& a : g.attachments()) {
    if (a->orbit() == o) return a.get();
  }
  return nullptr;
}

/// Calls f(x) with one dart x of each distinct sub-orbit <sub>(x) inside
/// <o>(d): the darts of GMap::for_each_sub_orbit, in its order.
template <class F>
void for_each_sub_orbit(const GMap& g, Dart d, Orbit o, Orbit sub, F&& f) {
  const OrbitAttachment* slots = attachment_on(g, sub);
  if (!slots) {
    g.for_each_sub_orbit(d, o, sub, f);
    return;
  }
  SubOrbitBuffers& b = sub_orbit_buffers();
  if (b.kept.size() <= b.depth) b.kept.resize(b.depth + 1);
  // The level is released even when f throws (an interrupt).
  struct Level {
    SubOrbitBuffers& b;
    ~Level() { --b.depth; }
  } level{b};
  // By index: a nested walk may grow b.kept and move this level's list.
  const std::size_t at = b.depth++;
  b.kept[at].clear();
  if (b.stamp.size() < slots->slot_capacity()) b.stamp.resize(slots->slot_capacity(), 0);
  if (++b.walk == 0) {  // the numbers wrapped: no stale stamp may match
    std::fill(b.stamp.begin(), b.stamp.end(), 0);
    b.walk = 1;
  }
  // The whole walk before any f: a nested walk (f's own folds) then reuses
  // the stamps freely.
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
    b.kept[at].push_back(x);
  });
  if (slotless) {
    g.for_each_sub_orbit(d, o, sub, f);
    return;
  }
  for (std::size_t k = 0; k < b.kept[at].size(); ++k)
    f(b.kept[at][k]);
}

}  // namespace rift::generated
