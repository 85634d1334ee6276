// Aggregates of an embedding over an orbit, as the rule language's folds
// compile them (docs/language.md "Aggregates"): each value counted once per
// embedding orbit inside the walked orbit, whatever the number of its darts.
// sum, count, mean, min and max of an empty set are 0, 0, 0, +max and lowest.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "rift/core/interrupt.hpp"
#include "rift/generated/scratch.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift::generated {

/// The additive zero of a value type of the language.
template <class T>
T zero() {
  if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>) {
    return T::Zero();
  } else {
    return T{};
  }
}

/// Calls f(value) once per slot of e met in the orbit <o>(d).
template <class T, class F>
void for_each_value(const GMap& g, const Embedding<T>& e, Dart d, Orbit o, F&& f) {
  // The darts of an embedding orbit share its slot. Where that orbit holds
  // <o>(d), the walk meets one value; where it is the single dart, every dart
  // its own: neither needs the search for values already met, which a
  // criterion on the edges of a large cloth would otherwise pay at each of them.
  const std::uint8_t on = e.orbit().mask();
  if ((on & o.mask()) == o.mask()) {
    if (e.slot(d) != kNoSlot) f(e[d]);
    return;
  }
  if (on == 0) {
    g.for_each_in_orbit(d, o, [&](Dart x) {
      throw_if_interrupted();
      if (e.slot(x) != kNoSlot) f(e[x]);
    });
    return;
  }
  Scratch& s = scratch();
  s.seen.clear();
  g.for_each_in_orbit(d, o, [&](Dart x) {
    throw_if_interrupted();  // orbits may be large (a polygon's face)
    const Slot slot = e.slot(x);
    if (slot == kNoSlot || std::find(s.seen.begin(), s.seen.end(), slot) != s.seen.end()) return;
    s.seen.push_back(slot);
    f(e[x]);
  });
}

template <class T>
T collect_sum(const GMap& g, const Embedding<T>& e, Dart d, Orbit o) {
  T acc = zero<T>();
  for_each_value(g, e, d, o, [&](const T& v) { acc = acc + v; });
  return acc;
}

template <class T>
std::int64_t collect_count(const GMap& g, const Embedding<T>& e, Dart d, Orbit o) {
  std::int64_t n = 0;
  for_each_value(g, e, d, o, [&](const T&) { ++n; });
  return n;
}

/// The mean of the values; of integers, a real.
template <class T>
auto collect_mean(const GMap& g, const Embedding<T>& e, Dart d, Orbit o) {
  const T sum = collect_sum(g, e, d, o);
  const auto n = static_cast<Real>(collect_count(g, e, d, o));
  if constexpr (std::is_same_v<T, std::int64_t>) {
    return n > 0 ? static_cast<Real>(sum) / n : Real(0);
  } else {
    return n > 0 ? T(sum / n) : zero<T>();
  }
}

template <class T>
T collect_min(const GMap& g, const Embedding<T>& e, Dart d, Orbit o) {
  T best = std::numeric_limits<T>::max();
  for_each_value(g, e, d, o, [&](const T& v) { best = std::min(best, v); });
  return best;
}

template <class T>
T collect_max(const GMap& g, const Embedding<T>& e, Dart d, Orbit o) {
  T best = std::numeric_limits<T>::lowest();
  for_each_value(g, e, d, o, [&](const T& v) { best = std::max(best, v); });
  return best;
}

}  // namespace rift::generated
