// The short form of a fold, `OP E over <o>(d)`, as generated code renders it
// when the fold's body is only the read of E at its dart (docs/language.md
// "Folds"): OP of E's value at one dart of each sub-orbit `sub` (= e ∩ o, e
// the orbit E is attached to) inside <o>(d), walked by for_each_sub_orbit.
// sum, count, mean, min and max of an empty set are 0, 0, 0, +max and lowest.
// A dart without a slot of E (none in a valid simulation) contributes nothing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "rift/generated/sub_orbits.hpp"
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

/// Whether every dart has a slot of e: a reader by dart (the slot is the
/// dart itself), which a fold then reads without testing for kNoSlot.
template <class E>
constexpr bool reads_every_dart() {
  if constexpr (requires { E::kReadBy; }) {
    return E::kReadBy == ReadBy::kDart;
  } else {
    return false;
  }
}

/// Calls f(value of e) at one dart of each sub-orbit <sub> of <o>(d).
// Inlined into the generated criteria, whose collect functions are too
// large for the compiler's own choice: a call per fold was a third of the
// atomic edge criterion's time.
// E: an Embedding or an EmbeddingReader of the value type.
template <class E, class F>
[[gnu::always_inline]] inline void for_each_value(const GMap& g, const E& e, Dart d, Orbit o,
                                                  Orbit sub, F&& f) {
  // The hottest folds, in a form small enough to inline: a value per dart
  // over one link (the atomic criteria's sum of f_stretch over each edge
  // end's <1>, every step): d, then its neighbour, as for_each_sub_orbit.
  if (o.size() == 1 && sub.size() == 0) {
    const Dart y = g.alpha(d, o.first());
    constexpr bool kEveryDart = reads_every_dart<E>();
    if (kEveryDart || e.slot(d) != kNoSlot) f(e[d]);
    if (y != d && (kEveryDart || e.slot(y) != kNoSlot)) f(e[y]);
    return;
  }
  for_each_sub_orbit(g, d, o, sub, [&](Dart x) {
    if (e.slot(x) != kNoSlot) f(e[x]);
  });
}

template <class E, class T = typename E::value_type>
[[gnu::always_inline]] inline T fold_sum(const GMap& g, const E& e, Dart d, Orbit o, Orbit sub) {
  T acc = zero<T>();
  for_each_value(g, e, d, o, sub, [&](const T& v) { acc = acc + v; });
  return acc;
}

/// The mean of the values; of integers, a real.
template <class E, class T = typename E::value_type>
[[gnu::always_inline]] inline auto fold_mean(const GMap& g, const E& e, Dart d, Orbit o,
                                             Orbit sub) {
  using R = std::conditional_t<std::is_same_v<T, std::int64_t>, Real, T>;
  R acc = zero<R>();
  std::int64_t n = 0;
  for_each_value(g, e, d, o, sub, [&](const T& v) {
    acc = acc + static_cast<R>(v);
    ++n;
  });
  return n > 0 ? R(acc / static_cast<Real>(n)) : zero<R>();
}

template <class E, class T = typename E::value_type>
[[gnu::always_inline]] inline T fold_min(const GMap& g, const E& e, Dart d, Orbit o, Orbit sub) {
  T best = std::numeric_limits<T>::max();
  for_each_value(g, e, d, o, sub, [&](const T& v) { best = std::min(best, v); });
  return best;
}

template <class E, class T = typename E::value_type>
[[gnu::always_inline]] inline T fold_max(const GMap& g, const E& e, Dart d, Orbit o, Orbit sub) {
  T best = std::numeric_limits<T>::lowest();
  for_each_value(g, e, d, o, sub, [&](const T& v) { best = std::max(best, v); });
  return best;
}

/// The number of sub-orbits <sub> of <o>(d): `count E over <o>(d)`.
inline std::int64_t count_sub_orbits(const GMap& g, Dart d, Orbit o, Orbit sub) {
  std::int64_t n = 0;
  for_each_sub_orbit(g, d, o, sub, [&](Dart) { ++n; });
  return n;
}

}  // namespace rift::generated
