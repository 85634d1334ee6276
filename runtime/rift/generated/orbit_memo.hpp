// Values a criterion computes once per orbit and collection (riftc's orbit
// memos, compiler/lower/orbit_memo.hpp). A criterion on vertices that folds
// over each vertex's tetrahedra reads, for every tetrahedron, values that
// depend on the tetrahedron alone (its mass, its Σ f ⊗ x): its four vertices
// would compute them four times. The first vertex that asks computes them;
// the other three read them back.
//
// An OrbitMemo numbers the orbits met in one collection: the first visit of
// an orbit stamps its key with the collection's number and the orbit's entry,
// so that any dart of the orbit finds the entry in O(1). The key is the
// orbit's slot where the map attaches embeddings to that orbit (criteria3d
// declares one on the volumes), otherwise each dart of the orbit. A new
// collection takes a new number, which leaves every stamp of the previous one
// stale without clearing anything: a value never outlives the collection that
// computed it, and so never sees a map changed by a tear. OrbitMemoValues<T>
// holds one value per entry; the memo remembers which values of an entry are
// computed (a value is computed only where the criterion asks for it).
//
// Storage is one stamp and one entry per slot (or dart) and one value per entry; it
// grows with the map and is reused from one collection to the next (no
// allocation per step once the map stops growing). Not thread-safe: one
// collection at a time per memo.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rift/generated/sub_orbits.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift::generated {

class OrbitMemo {
 public:
  /// Starts a collection on `g` for orbits <o>: every orbit is unvisited.
  void begin(const GMap& g, Orbit o) {
    // Where the map attaches embeddings to <o>, every dart of an orbit holds
    // the orbit's slot: the slot is the key, found without walking the orbit.
    slots_ = attachment_on(g, o);
    grow(by_slot_, slots_ ? slots_->slot_capacity() : 0);
    grow(by_dart_, g.capacity());
    known_.clear();
    if (++collection_ == 0) {  // the numbers wrapped: no stale stamp may match
      std::fill(by_slot_.stamp.begin(), by_slot_.stamp.end(), 0);
      std::fill(by_dart_.stamp.begin(), by_dart_.stamp.end(), 0);
      collection_ = 1;
    }
  }

  /// The entry of the orbit <o>(d) in this collection, numbered on its first visit.
  std::uint32_t entry(const GMap& g, Dart d, Orbit o) {
    const Slot slot = slots_ ? slots_->slot(d) : kNoSlot;
    if (slot != kNoSlot) {
      if (by_slot_.stamp[slot] == collection_) return by_slot_.entry[slot];
      const std::uint32_t e = add_entry();
      by_slot_.stamp[slot] = collection_;
      by_slot_.entry[slot] = e;
      return e;
    }
    // No slot: every dart of the orbit is stamped (one walk per orbit and collection).
    if (by_dart_.stamp[d] == collection_) return by_dart_.entry[d];
    const std::uint32_t e = add_entry();
    g.for_each_in_orbit(d, o, [&](Dart x) {
      by_dart_.stamp[x] = collection_;
      by_dart_.entry[x] = e;
    });
    return e;
  }

  /// Whether value `k` (< 64) of entry `e` is computed, and marking it so.
  bool known(std::uint32_t e, unsigned k) const { return (known_[e] >> k) & 1U; }
  void set_known(std::uint32_t e, unsigned k) { known_[e] |= std::uint64_t{1} << k; }
  /// Orbits visited in this collection.
  std::size_t entries() const { return known_.size(); }

 private:
  /// Per key (a slot or a dart): the collection that last visited its orbit, and the orbit's entry
  /// then.
  struct Stamps {
    std::vector<std::uint32_t> stamp;
    std::vector<std::uint32_t> entry;
  };
  static void grow(Stamps& s, std::size_t n) {
    if (s.stamp.size() >= n) return;
    s.stamp.resize(n, 0);
    s.entry.resize(n, 0);
  }
  std::uint32_t add_entry() {
    known_.push_back(0);
    return static_cast<std::uint32_t>(known_.size() - 1);
  }

  const OrbitAttachment* slots_ = nullptr;  // the map's attachment on the memo's orbit, if any
  Stamps by_slot_, by_dart_;
  std::vector<std::uint64_t> known_;  // per entry: bit k set when value k is computed
  std::uint32_t collection_ = 0;
};

/// Value `k` of each entry of an OrbitMemo.
template <class T>
class OrbitMemoValues {
 public:
  /// The value of entry `e`, computed by `compute()` on the first request of this collection.
  template <class F>
  const T& get(OrbitMemo& memo, std::uint32_t e, unsigned k, F&& compute) {
    if (values_.size() <= e) values_.resize(memo.entries());
    if (!memo.known(e, k)) {
      values_[e] = compute();
      memo.set_known(e, k);
    }
    return values_[e];
  }

 private:
  std::vector<T> values_;
};

}  // namespace rift::generated
