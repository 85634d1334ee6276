// What a generated pack needs from the map and the scene at set-up: a
// component's parameter values, the embeddings its code reads, and the dart
// an element was tagged with when it was initialised.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "rift/embed/value.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift::generated {

/// A parameter value given by a scene or a caller, as T (an int is accepted
/// for a real). Throws std::invalid_argument naming `what` otherwise.
template <class T>
T value_as(const Value& v, const std::string& what) {
  if constexpr (std::is_same_v<T, Real>) {
    if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<Real>(*i);
  }
  if constexpr (std::is_same_v<T, bool>) {
    if (const auto* b = std::get_if<Bool>(&v)) return b->value;
  } else {
    if (const auto* x = std::get_if<T>(&v)) return *x;
  }
  throw std::invalid_argument(what + " has a value of the wrong type");
}

/// The dart of <o>(d) tagged at initialisation (§3.2: the first dart fixes the
/// order of an element's vertices), or kNoDart.
inline Dart tagged_dart(const GMap& g, const Embedding<Bool>& tag, Dart d, Orbit o) {
  if (tag[d]) return d;
  Dart found = kNoDart;
  g.for_each_in_orbit(d, o, [&](Dart x) {
    if (found == kNoDart && tag[x]) found = x;
  });
  return found;
}

/// The support dart of an untagged interaction on <o>(d): the dart of the
/// orbit whose match binds the smallest vertex slots first (lexicographic
/// order of the N vertex slots that key(Dart x, Slot* key, Dart* found) ->
/// bool writes for a dart that matches, with the D darts of the pattern
/// found from x; ties go to the smaller dart). The language lets an
/// untagged interaction be matched from any dart of its support orbit; this
/// one makes the choice a function of the vertices, so two matches on the
/// same vertices (the two half-edges of an edge, one per face) bind them in
/// the same order and can be evaluated once (rift/sim/match_groups.hpp).
/// The inits and the simulator's match cache use the same dart, once per
/// orbit: the dart is chosen when the orbit is first matched and kept after.
/// `darts` gets the pattern's darts found from the chosen dart, which the
/// inits then need not find again. kNoDart when no dart of the orbit matches.
template <int N, int D, class KeyFn>
Dart smallest_support_match(const GMap& g, Dart d, Orbit o, Dart* darts, KeyFn&& key) {
  static_assert(N > 0 && D > 0);
  Dart best = kNoDart;
  Slot best_key[N] = {};
  Slot k[N] = {};
  Dart found[D];
  g.for_each_in_orbit(d, o, [&](Dart x) {
    if (!key(x, k, found)) return;
    if (best == kNoDart || std::lexicographical_compare(k, k + N, best_key, best_key + N) ||
        (std::equal(k, k + N, best_key) && x < best)) {
      best = x;
      std::copy(k, k + N, best_key);
      std::copy(found, found + D, darts);
    }
  });
  return best;
}

/// The map's embedding `name` of type T; `user` (e.g. "interaction 'stretch'")
/// names who reads it in the error when the map does not have it.
template <class T>
Embedding<T> require_embedding(const GMap& g, const char* name, const char* user) {
  Embedding<T> e = g.embedding<T>(name);
  if (!e) {
    throw std::invalid_argument(std::string(user) + " reads embedding '" + name +
                                "', which the map does not have (call declare_embeddings first)");
  }
  return e;
}

}  // namespace rift::generated
