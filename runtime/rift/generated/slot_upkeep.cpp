#include "rift/generated/slot_upkeep.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "rift/core/prefetch.hpp"

namespace rift::generated {

namespace {

// The slots the orbits met so far in one attachment kept ("claimed"), for
// one rewrite: open addressing in a table of at least twice as many
// positions as the rewrite has darts (an attachment has at most one orbit
// per dart), so that a lookup is a probe or two. A scan of the claimed list
// per lookup made the upkeep quadratic in the rewrite's size: 30 k
// instructions of a spring split's 220 k, most of them in per-dart
// attachments (72 orbits, 72 claimed slots).
class ClaimedSlots {
 public:
  ClaimedSlots(std::vector<Slot>& table, std::size_t darts) : table_(table) {
    std::size_t size = 16;
    while (size < 2 * darts)
      size *= 2;
    table_.assign(size, kNoSlot);
    mask_ = size - 1;
  }
  bool contains(Slot slot) const {
    for (std::size_t i = home(slot);; i = (i + 1) & mask_) {
      if (table_[i] == slot) return true;
      if (table_[i] == kNoSlot) return false;
    }
  }
  void insert(Slot slot) {
    std::size_t i = home(slot);
    while (table_[i] != kNoSlot && table_[i] != slot)
      i = (i + 1) & mask_;
    table_[i] = slot;
  }

 private:
  std::size_t home(Slot slot) const {
    return static_cast<std::size_t>((std::uint64_t{slot} * 0x9e3779b97f4a7c15ull) >> 32) & mask_;
  }
  std::vector<Slot>& table_;
  std::size_t mask_ = 0;
};

// update_embedding_slots for a per-dart attachment (<>), which is by dart
// (attachment.hpp): each dart is its own orbit and its slot is the dart, so
// the general case's orbit walk, lists and merges reduce to giving each dart
// without its value (new, or an index taken again) its own slot with the
// defaults. Only rewrites that create or delete darts come here (the others
// skip per-dart attachments, whose orbits they cannot change).
void update_dart_slots(GMap& g, OrbitAttachment& att, const Dart* darts, std::size_t count,
                       std::vector<Dart>* touched) {
  for (std::size_t k = 0; k < count; ++k) {
    const Dart x = darts[k];
    if (!g.is_alive(x) || att.slot(x) != kNoSlot) continue;
    att.hold(x);  // a dart listed twice is held at its first listing
    if (touched) touched->push_back(x);
  }
}

}  // namespace

void update_embedding_slots(GMap& g, const Dart* darts, std::size_t count, Scratch& s,
                            std::vector<Dart>* touched, RewriteChanges changes) {
  // Every awake attachment's slots of the rewritten darts, asked for before
  // the first is read: on a large map each attachment's slot array is a miss
  // per dart, and the loops below would take them one after the other.
  if (g.capacity() >= kPrefetchFromDarts) {
    for (const auto& attachment : g.attachments()) {
      if (attachment->dormant() || !changes.may_change(attachment->orbit())) continue;
      const Slot* slots = attachment->slot_data();
      if (!slots) continue;  // by dart: nothing to read
      for (std::size_t k = 0; k < count; ++k)
        prefetch(slots + darts[k]);
    }
  }
  for (const auto& attachment : g.attachments()) {
    OrbitAttachment& att = *attachment;
    if (att.dormant()) continue;  // no slots until a column is asked for
    // Its orbits are the ones before the rewrite (the 2-links a face
    // separation changes leave every edge, corner and face as it was): four
    // of a cloth's six attachments after a tear.
    if (!changes.may_change(att.orbit())) continue;
    if (att.orbit().empty()) {
      update_dart_slots(g, att, darts, count, touched);
      continue;
    }
    const Mark m = g.reserve_mark();
    ClaimedSlots claimed(s.claimed, count);
    s.marked.clear();
    for (std::size_t k = 0; k < count; ++k) {
      if (g.is_marked(darts[k], m)) continue;
      s.orbit.clear();
      s.slots.clear();
      g.for_each_in_orbit(darts[k], att.orbit(), [&](Dart x) { s.orbit.push_back(x); });
      for (Dart x : s.orbit) {
        g.mark(x, m);
        s.marked.push_back(x);
        const Slot slot = att.slot(x);
        if (slot != kNoSlot && std::find(s.slots.begin(), s.slots.end(), slot) == s.slots.end())
          s.slots.push_back(slot);
      }
      // A slot already kept by another orbit of this rewrite is "claimed": an
      // orbit that finds only claimed slots was split off and takes a copy.
      Slot keep = kNoSlot;
      for (Slot slot : s.slots) {
        if (!claimed.contains(slot)) {
          keep = slot;
          break;
        }
      }
      if (s.slots.empty()) {
        keep = att.allocate_slot();
      } else if (keep == kNoSlot) {
        keep = att.allocate_slot();
        for (const auto& column : att.columns())
          column->copy_slot(s.slots[0], keep);
      } else {
        for (Slot other : s.slots) {
          if (other == keep || claimed.contains(other)) continue;
          for (const auto& column : att.columns())
            column->merge_into(keep, other);
        }
      }
      claimed.insert(keep);
      for (Dart x : s.orbit) {
        if (att.slot(x) == keep) continue;
        att.assign(x, keep);
        if (touched) touched->push_back(x);
      }
    }
    for (Dart x : s.marked)
      g.unmark(x, m);
    g.free_mark(m);
  }
}

}  // namespace rift::generated
