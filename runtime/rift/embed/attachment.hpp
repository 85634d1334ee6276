// All embeddings attached to one orbit type share one slot index per dart:
// every dart of an orbit holds the same slot, so reading a value is
// `column[slot_of_dart[d]]`, O(1), and the columns themselves are dense arrays
// that integrators sweep directly.
//
// An attachment is *dormant* until one of its columns is asked for
// (GMap::embedding, GMap::attachment_of): it then keeps no slot per dart and
// no dart count per slot, and every topology change passes it by. Packs
// declare embeddings on orbits that a scene may never use (a quad cloth without
// angular springs never reads the <0,2> orbit's parameters; the hexahedra's
// <1> orbit holds only shear forces that nothing reads): at 4.8e7 darts each
// such slot array was 192 MB to fill at set-up and keep (issue 12, lean memory).
//
// An attachment on <> (values per dart: stored forces at each end of a spring,
// an interaction's tag) is *by dart*: each dart is its own orbit and its slot
// is the dart itself. It keeps no slot per dart and no dart count per slot (8
// bytes a dart: 355 MB of a 4.7·10⁷-dart hexahedral block, 237 MB of a
// 1.3·10⁶-tetrahedron block for one tag bit a dart), only one bit a dart
// saying whether the dart holds its value (it is alive and its value was set
// up). Its columns have one value per dart of the map. Two darts never share
// a value there: a dart given another's slot (assign) takes a copy of its
// values, and a dart that takes its own (hold) starts from the defaults.
#pragma once

#include <cassert>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "rift/core/huge_pages.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/orbit.hpp"
#include "rift/embed/column.hpp"

namespace rift {

class OrbitAttachment {
 public:
  explicit OrbitAttachment(Orbit orbit) : orbit_(orbit), by_dart_(orbit.empty()) {}

  Orbit orbit() const { return orbit_; }
  /// True for <>: the slot of a dart is the dart (see the file comment), and
  /// slot_data() is null.
  bool by_dart() const { return by_dart_; }
  /// True while the attachment keeps no slots (see the file comment): slot()
  /// must not be called, and every column reads as its default.
  bool dormant() const { return dormant_; }
  /// Ends dormancy with room for `darts` darts, none holding a slot yet;
  /// GMap::wake then gives every orbit its slot.
  void wake(std::size_t darts) {
    dormant_ = false;
    resize_darts(darts);
  }
  Slot slot(Dart d) const {
    if (by_dart_) return holds(d) ? d : kNoSlot;
    return slot_of_dart_[d];
  }
  /// The slot of each dart, or null for an attachment by dart (whose slot of
  /// a live dart is the dart).
  const Slot* slot_data() const { return by_dart_ ? nullptr : slot_of_dart_.data(); }

  /// Number of slot indices in use or free; columns have this many values.
  std::size_t slot_capacity() const { return by_dart_ ? darts_ : dart_count_.size(); }
  /// A slot is alive while at least one dart refers to it.
  bool slot_alive(Slot s) const { return by_dart_ ? holds(s) : dart_count_[s] > 0; }
  std::uint32_t darts_in_slot(Slot s) const {
    if (by_dart_) return holds(s) ? 1 : 0;
    return dart_count_[s];
  }
  std::size_t live_slots() const {
    return by_dart_ ? slotted_darts_ : dart_count_.size() - free_slots_.size();
  }
  /// Darts holding a slot (dead darts hold none: GMap::delete_dart releases
  /// them), kept by assign and release so that GMap::slotted_attachment
  /// knows without a pass over the darts whether every live dart has one.
  std::size_t slotted_darts() const { return slotted_darts_; }
  /// Slots no dart owns (reused first by allocate_slot); none by dart (a
  /// dead dart's slot is the dart's, taken again with it).
  const std::vector<Slot>& free_slots() const { return free_slots_; }

  const std::vector<std::unique_ptr<ColumnBase>>& columns() const { return columns_; }
  ColumnBase* find_column(std::string_view name) const {
    for (const auto& c : columns_) {
      if (c->name() == name) return c.get();
    }
    return nullptr;
  }

  /// Its slot arrays as "attachment <o>", each column's values as "column NAME".
  void report_memory(MemoryReport& report) const {
    const std::string owner = "attachment " + orbit_.str();
    report.add(owner, "slot of each dart", slot_of_dart_);
    report.add(owner, "darts of each slot", dart_count_);
    report.add(owner, "free slots", free_slots_);
    report.add(owner, "darts holding their value (bits)", held_);
    for (const auto& c : columns_)
      report.add("column " + c->name(), "values", c->bytes());
  }

  // ---- used by GMap when topology changes -------------------------------

  void add_column(std::unique_ptr<ColumnBase> column) {
    column->resize(slot_capacity());
    columns_.push_back(std::move(column));
  }
  void resize_darts(std::size_t capacity) {
    if (dormant_) return;
    if (by_dart_) {
      if (capacity <= darts_) return;
      grow_huge(held_, (capacity + 63) / 64, std::uint64_t{0});
      darts_ = capacity;
      grow_columns();
      return;
    }
    grow_huge(slot_of_dart_, capacity, kNoSlot);
  }

  /// By dart: d takes its own slot, its values the defaults (a dart index
  /// taken again must not read what its dead predecessor left).
  void hold(Dart d) {
    if (holds(d)) return;
    for (auto& c : columns_)
      c->set_default(d);
    set_held(d);
  }

  /// By dart, an attachment just woken (wake): d takes its own slot, whose
  /// values are still the defaults the columns were grown with, so they are
  /// not written a second time (a pass over 1 GB of stored stretch forces on
  /// a 10^6-vertex hexahedral block's set-up).
  void hold_as_grown(Dart d) {
    if (!holds(d)) set_held(d);
  }

  /// A fresh slot holding every column's default value, not yet owned by any dart.
  Slot allocate_slot() {
    const Slot s = reserve_slot();
    grow_columns();
    return s;
  }

  /// Room for n slots in all (e.g. one per dart before a fresh attachment's
  /// walk), advised for huge pages: reserve_slot then neither moves the dart
  /// counts nor faults them in 4 KiB at a time (issue 12's set-up).
  void reserve_slots(std::size_t n) {
    if (!by_dart_) reserve_huge(dart_count_, n);
  }

  /// A fresh slot like allocate_slot, but a slot past the columns' end is
  /// left for grow_columns() to fill: giving many orbits slots at once then
  /// grows each column once rather than once per slot.
  Slot reserve_slot() {
    if (by_dart_) throw std::logic_error("an attachment by dart gives no slot apart from a dart's");
    if (free_slots_.empty()) {
      dart_count_.push_back(0);
      return static_cast<Slot>(dart_count_.size() - 1);
    }
    const Slot s = free_slots_.back();
    free_slots_.pop_back();
    for (auto& c : columns_)
      c->set_default(s);
    return s;
  }
  /// Gives every column a value (the default) for each slot reserve_slot appended.
  void grow_columns() {
    for (auto& c : columns_)
      c->resize(slot_capacity());
  }

  void assign(Dart d, Slot s) {
    if (by_dart_) {
      // d takes the values of slot s (its own: nothing to copy).
      if (s != d) {
        for (auto& c : columns_)
          c->copy_slot(s, d);
      }
      if (!holds(d)) set_held(d);
      return;
    }
    release(d);
    slot_of_dart_[d] = s;
    ++dart_count_[s];
    ++slotted_darts_;
  }

  /// A fresh attachment's numbering (GMap::give_missing_slots): the darts of
  /// one orbit, which hold no slot yet, take slot s; for_each(claim) calls
  /// claim(d) for each. The counts are kept in registers and written once:
  /// assign's release and by-dart branches made it an out-of-line call per
  /// dart, and a count incremented in memory per dart chained each step of
  /// the walk to the one before (most of a 10^6-vertex cloth's slot
  /// numbering, issue 12).
  template <class ForEach>
  void claim_orbit(Slot s, ForEach&& for_each) {
    assert(!by_dart_);
    Slot* slots = slot_of_dart_.data();
    std::uint32_t count = 0;
    for_each([&](Dart d) {
      assert(slots[d] == kNoSlot);
      slots[d] = s;
      ++count;
    });
    dart_count_[s] += count;
    slotted_darts_ += count;
  }

  void release(Dart d) {
    if (dormant_) return;
    if (by_dart_) {
      if (holds(d)) clear_held(d);
      return;
    }
    Slot old = slot_of_dart_[d];
    if (old == kNoSlot) return;
    slot_of_dart_[d] = kNoSlot;
    --slotted_darts_;
    if (--dart_count_[old] == 0) free_slots_.push_back(old);
  }

  /// Renumbers darts after compaction: new_index[old] (kNoDart for dead darts).
  void remap_darts(const std::vector<Dart>& new_index, std::size_t new_capacity) {
    if (dormant_) return;
    if (by_dart_) {
      // Values move with their darts, to lower indices: in increasing order
      // a value is copied before its place is written.
      std::vector<std::uint64_t> held((new_capacity + 63) / 64, 0);
      for (std::size_t old = 0; old < new_index.size(); ++old) {
        const Dart to = new_index[old];
        if (to == kNoDart || !holds(static_cast<Dart>(old))) continue;
        if (to != old) {
          for (auto& c : columns_)
            c->copy_slot(static_cast<Slot>(old), to);
        }
        set_bit(held, to);
      }
      held_ = std::move(held);
      darts_ = new_capacity;
      for (auto& c : columns_)
        c->resize(new_capacity);
      return;
    }
    std::vector<Slot> remapped(new_capacity, kNoSlot);
    for (std::size_t old = 0; old < new_index.size(); ++old) {
      if (new_index[old] != kNoDart) remapped[new_index[old]] = slot_of_dart_[old];
    }
    slot_of_dart_ = std::move(remapped);
  }

  /// Packs live slots to [0, live_slots()), keeping their order.
  void compact_slots() {
    if (dormant_ || by_dart_) return;  // by dart: compacted with the darts
    std::vector<Slot> new_slot(dart_count_.size(), kNoSlot);
    Slot next = 0;
    for (Slot s = 0; s < dart_count_.size(); ++s) {
      if (dart_count_[s] == 0) continue;
      for (auto& c : columns_)
        c->copy_slot(s, next);
      dart_count_[next] = dart_count_[s];
      new_slot[s] = next++;
    }
    dart_count_.resize(next);
    for (auto& c : columns_)
      c->resize(next);
    free_slots_.clear();
    for (Slot& s : slot_of_dart_) {
      if (s != kNoSlot) s = new_slot[s];
    }
  }

 private:
  bool holds(Dart d) const { return d < darts_ && (held_[d / 64] >> (d % 64) & 1) != 0; }
  static void set_bit(std::vector<std::uint64_t>& bits, Dart d) {
    bits[d / 64] |= std::uint64_t{1} << (d % 64);
  }
  // By dart: d starts or stops holding its value (the bit and the count).
  void set_held(Dart d) {
    set_bit(held_, d);
    ++slotted_darts_;
  }
  void clear_held(Dart d) {
    held_[d / 64] &= ~(std::uint64_t{1} << (d % 64));
    --slotted_darts_;
  }

  Orbit orbit_;
  bool by_dart_;
  bool dormant_ = true;
  std::size_t darts_ = 0;            ///< by dart: darts covered (slot_capacity)
  std::vector<std::uint64_t> held_;  ///< by dart: one bit a dart holding its value
  std::vector<Slot> slot_of_dart_;
  std::vector<std::uint32_t> dart_count_;
  std::vector<Slot> free_slots_;
  std::size_t slotted_darts_ = 0;
  std::vector<std::unique_ptr<ColumnBase>> columns_;
};

}  // namespace rift
