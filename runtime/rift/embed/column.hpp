// A typed column of embedding values, indexed by slot (one slot per orbit).
//
// A column holds no storage until it is first asked for its values (issue 12,
// lean memory): a pack declares every embedding its interactions might use,
// but a scene that uses only some of them pays only for those. While a column
// is unallocated every slot reads as the default, which is exactly what its
// storage would hold, so topology changes (copy, merge, compaction) have
// nothing to do for it.
//
// A column may also be *withheld* (GMap::withhold_storage): the scene's set-up
// does so for the stored forces that nothing of the scene reads, and for the
// ones that no interaction of the scene writes. GMap::embedding then hands out
// the column without storage; const reads through the handle give the default,
// and the first mutable access (values(), a write) allocates it.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "rift/core/huge_pages.hpp"
#include "rift/embed/value.hpp"

namespace rift {

/// Type-erased face of a column, used only when topology changes (split,
/// merge, compaction); hot loops use the typed Column<T> directly.
class ColumnBase {
 public:
  ColumnBase(std::string name, ValueType type, MergePolicy policy)
      : name_(std::move(name)), type_(type), policy_(policy) {}
  virtual ~ColumnBase() = default;
  ColumnBase(const ColumnBase&) = delete;
  ColumnBase& operator=(const ColumnBase&) = delete;

  const std::string& name() const { return name_; }
  ValueType type() const { return type_; }
  MergePolicy policy() const { return policy_; }

  /// True once the column has storage (see the file comment).
  bool allocated() const { return allocated_.load(std::memory_order_acquire); }
  /// Gives the column storage for every slot, holding the default value.
  virtual void allocate() = 0;
  /// True when GMap::embedding leaves the column without storage (see the file comment).
  bool withheld() const { return withheld_; }
  void set_withheld(bool on) { withheld_ = on; }

  virtual void resize(std::size_t slots) = 0;
  virtual void copy_slot(Slot from, Slot to) = 0;
  /// Combines the value of `from` into `into` following the merge policy.
  virtual void merge_into(Slot into, Slot from) = 0;
  virtual bool equal(Slot a, Slot b) const = 0;
  virtual void set_default(Slot s) = 0;
  virtual Value get(Slot s) const = 0;
  virtual void set(Slot s, const Value& v) = 0;
  virtual std::unique_ptr<ColumnBase> clone() const = 0;
  /// Bytes of the values stored (0 while the column has no storage).
  virtual std::size_t bytes() const = 0;

 protected:
  // Atomic, with allocate() under a lock: a withheld column may be allocated
  // by its first mutable access, which a parallel pass could make.
  std::atomic<bool> allocated_ = false;
  std::mutex allocating_;

 private:
  bool withheld_ = false;
  std::string name_;
  ValueType type_;
  MergePolicy policy_;
};

template <class T>
class Column final : public ColumnBase {
 public:
  Column(std::string name, MergePolicy policy, T default_value)
      : ColumnBase(std::move(name), ValueTypeOf<T>::value, policy),
        default_(std::move(default_value)) {
    T merged = default_;
    merge(merged, default_);
    default_survives_merge_ = merged == default_;
  }

  /// The values by slot. GMap::embedding allocates a column that is not
  /// withheld; a withheld one gets its storage here, at its first use.
  std::vector<T>& values() {
    if (!allocated()) allocate();
    return values_;
  }
  const std::vector<T>& values() const {
    if (!allocated()) const_cast<Column*>(this)->allocate();
    return values_;
  }
  /// The value of slot s, the default while the column has no storage.
  const T& read(Slot s) const { return allocated() ? values_[s] : default_; }
  /// The values by slot, or null while the column has no storage (readers
  /// then read the default: EmbeddingReader).
  const T* storage() const { return allocated() ? values_.data() : nullptr; }
  const T& default_value() const { return default_; }

  void allocate() override {
    if (allocated()) return;
    const std::lock_guard<std::mutex> lock(allocating_);
    if (allocated()) return;
    grow_huge(values_, slots_, default_);
    allocated_.store(true, std::memory_order_release);
  }
  void resize(std::size_t slots) override {
    slots_ = slots;
    if (allocated()) grow_huge(values_, slots, default_);
  }
  void copy_slot(Slot from, Slot to) override {
    if (allocated()) values_[to] = values_[from];
  }
  void merge_into(Slot into, Slot from) override {
    if (!allocated()) {
      // Two defaults merge into the default under every policy but a sum of
      // non-zero defaults: only then does the merged value need storage.
      if (default_survives_merge_) return;
      allocate();
    }
    merge(values_[into], values_[from]);
  }
  bool equal(Slot a, Slot b) const override { return !allocated() || values_[a] == values_[b]; }
  void set_default(Slot s) override {
    if (allocated()) values_[s] = default_;
  }
  Value get(Slot s) const override { return read(s); }
  void set(Slot s, const Value& v) override {
    const T& value = std::get<T>(v);
    if (!allocated()) {
      if (value == default_) return;
      allocate();
    }
    values_[s] = value;
  }
  std::unique_ptr<ColumnBase> clone() const override {
    auto c = std::make_unique<Column<T>>(name(), policy(), default_);
    c->values_ = values_;
    c->slots_ = slots_;
    c->allocated_.store(allocated(), std::memory_order_relaxed);
    c->set_withheld(withheld());
    return c;
  }
  std::size_t bytes() const override { return values_.size() * sizeof(T); }

 private:
  void merge(T& a, const T& b) const {
    switch (policy()) {
      case MergePolicy::kKeepFirst:
      case MergePolicy::kRefuse:
        break;
      case MergePolicy::kSum:
        if constexpr (std::is_same_v<T, Bool>) {
          a = a || b;
        } else {
          a = a + b;
        }
        break;
      case MergePolicy::kMean:
        if constexpr (std::is_same_v<T, Bool>) {
          a = a || b;
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          a = (a + b) / 2;
        } else {
          a = (a + b) * Real(0.5);
        }
        break;
    }
  }

  std::vector<T> values_;
  std::size_t slots_ = 0;  // the attachment's slot capacity, allocated or not
  T default_;
  bool default_survives_merge_ = true;
};

}  // namespace rift
