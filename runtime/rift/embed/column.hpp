// A typed column of embedding values, indexed by slot (one slot per orbit).
#pragma once

#include <memory>
#include <string>
#include <vector>

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

  virtual void resize(std::size_t slots) = 0;
  virtual void copy_slot(Slot from, Slot to) = 0;
  /// Combines the value of `from` into `into` following the merge policy.
  virtual void merge_into(Slot into, Slot from) = 0;
  virtual bool equal(Slot a, Slot b) const = 0;
  virtual void set_default(Slot s) = 0;
  virtual Value get(Slot s) const = 0;
  virtual void set(Slot s, const Value& v) = 0;
  virtual std::unique_ptr<ColumnBase> clone() const = 0;

 private:
  std::string name_;
  ValueType type_;
  MergePolicy policy_;
};

template <class T>
class Column final : public ColumnBase {
 public:
  Column(std::string name, MergePolicy policy, T default_value)
      : ColumnBase(std::move(name), ValueTypeOf<T>::value, policy),
        default_(std::move(default_value)) {}

  std::vector<T>& values() { return values_; }
  const std::vector<T>& values() const { return values_; }
  const T& default_value() const { return default_; }

  void resize(std::size_t slots) override { values_.resize(slots, default_); }
  void copy_slot(Slot from, Slot to) override { values_[to] = values_[from]; }
  void merge_into(Slot into, Slot from) override {
    T& a = values_[into];
    const T& b = values_[from];
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
  bool equal(Slot a, Slot b) const override { return values_[a] == values_[b]; }
  void set_default(Slot s) override { values_[s] = default_; }
  Value get(Slot s) const override { return values_[s]; }
  void set(Slot s, const Value& v) override { values_[s] = std::get<T>(v); }
  std::unique_ptr<ColumnBase> clone() const override {
    auto c = std::make_unique<Column<T>>(name(), policy(), default_);
    c->values_ = values_;
    return c;
  }

 private:
  std::vector<T> values_;
  T default_;
};

}  // namespace rift
