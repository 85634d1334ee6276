// Where a simulation's memory goes, by owner and array: `rift bench --json`
// reports it as `memory`. The peak resident set of a large mesh says how much
// memory a scene takes, not which state holds it; issue 12's set-up and
// memory rows needed that breakdown measured (a 10^6-vertex hexahedral
// block's 6.3 GB), and a user who brings a large mesh needs it to know what
// to leave out (a criterion that keeps a force on every dart, say).
//
// Each array counts the bytes of its elements in use (size(), not
// capacity()): the runtime reserves large arrays ahead without touching them
// (reserve_huge), and untouched pages take no memory.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rift {

class MemoryReport {
 public:
  struct Item {
    std::string owner;  ///< "map", "attachment <0>", "column f_stretch", "interaction stretch", ...
    std::string what;   ///< the array within its owner
    std::size_t bytes = 0;
  };

  /// Adds `bytes` for owner/what; empty arrays are not listed.
  void add(std::string_view owner, std::string_view what, std::size_t bytes) {
    if (bytes > 0) items_.push_back({std::string(owner), std::string(what), bytes});
  }
  template <class T>
  void add(std::string_view owner, std::string_view what, const std::vector<T>& array) {
    add(owner, what, array.size() * sizeof(T));
  }

  const std::vector<Item>& items() const { return items_; }
  std::size_t total() const {
    std::size_t sum = 0;
    for (const Item& i : items_)
      sum += i.bytes;
    return sum;
  }
  /// The bytes listed for one owner.
  std::size_t of(std::string_view owner) const {
    std::size_t sum = 0;
    for (const Item& i : items_) {
      if (i.owner == owner) sum += i.bytes;
    }
    return sum;
  }

 private:
  std::vector<Item> items_;
};

}  // namespace rift
