// A growable list of trivially copyable values whose append is always
// inlined: a compare, a store and an increment, the growth out of line.
//
// std::vector::push_back carries its reallocation path with it, and inside a
// large function (MatchCache::rematch, instantiated per kernel) GCC's inliner
// gave up on it: every append of a re-match's frontier and seen darts was a
// call, 8 % of a tear's instructions. A list kept for scratch, reserved once
// and cleared between uses, does not need the rest of std::vector.
#pragma once

#include <cstddef>
#include <cstring>
#include <memory>
#include <type_traits>

namespace rift {

template <class T>
class FlatList {
  static_assert(std::is_trivially_copyable_v<T>, "FlatList holds trivially copyable values");

 public:
  FlatList() = default;
  FlatList(const FlatList&) = delete;
  FlatList& operator=(const FlatList&) = delete;
  FlatList(FlatList&&) noexcept = default;
  FlatList& operator=(FlatList&&) noexcept = default;
  ~FlatList() = default;

  [[gnu::always_inline]] void push_back(T x) {
    if (size_ == capacity_) [[unlikely]]
      grow(capacity_ == 0 ? 16 : 2 * capacity_);
    data_[size_++] = x;
  }
  void clear() { size_ = 0; }
  /// Room for n values without growing; keeps the values held.
  void reserve(std::size_t n) {
    if (n > capacity_) grow(n);
  }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  const T* begin() const { return data_.get(); }
  const T* end() const { return data_.get() + size_; }

 private:
  [[gnu::noinline]] void grow(std::size_t capacity) {
    std::unique_ptr<T[]> bigger(new T[capacity]);
    if (size_ > 0) std::memcpy(bigger.get(), data_.get(), size_ * sizeof(T));
    data_ = std::move(bigger);
    capacity_ = capacity;
  }

  std::unique_ptr<T[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace rift
