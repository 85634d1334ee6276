#include "rift/generated/slot_upkeep.hpp"

#include <algorithm>

#include "rift/core/prefetch.hpp"

namespace rift::generated {

void update_embedding_slots(GMap& g, const Dart* darts, std::size_t count, Scratch& s,
                            std::vector<Dart>* touched) {
  // Every awake attachment's slots of the rewritten darts, asked for before
  // the first is read: on a large map each attachment's slot array is a miss
  // per dart, and the loops below would take them one after the other.
  if (g.capacity() >= kPrefetchFromDarts) {
    for (const auto& attachment : g.attachments()) {
      if (attachment->dormant()) continue;
      const Slot* slots = attachment->slot_data();
      for (std::size_t k = 0; k < count; ++k)
        prefetch(slots + darts[k]);
    }
  }
  for (const auto& attachment : g.attachments()) {
    OrbitAttachment& att = *attachment;
    if (att.dormant()) continue;  // no slots until a column is asked for
    const Mark m = g.reserve_mark();
    s.claimed.clear();
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
      auto claimed = [&](Slot slot) {
        return std::find(s.claimed.begin(), s.claimed.end(), slot) != s.claimed.end();
      };
      Slot keep = kNoSlot;
      for (Slot slot : s.slots) {
        if (!claimed(slot)) {
          keep = slot;
          break;
        }
      }
      if (s.slots.empty()) {
        keep = att.allocate_slot();
      } else if (keep == kNoSlot) {
        keep = att.allocate_slot();
        for (const auto& column : att.columns())
          column->copy_slot(s.slots.front(), keep);
      } else {
        for (Slot other : s.slots) {
          if (other == keep || claimed(other)) continue;
          for (const auto& column : att.columns())
            column->merge_into(keep, other);
        }
      }
      s.claimed.push_back(keep);
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
