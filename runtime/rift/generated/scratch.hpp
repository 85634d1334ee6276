// Buffers reused by the code riftc generates (matching, rewriting, orbit
// aggregates), one set per thread: after warm-up, matching and rewriting do
// not allocate. Each user touches only its own fields and leaves them empty
// or reset, so the same set serves every pack.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rift/core/flat_list.hpp"
#include "rift/core/types.hpp"

namespace rift::generated {

inline constexpr std::uint32_t kNoRow = 0xFFFFFFFFu;

struct Scratch {
  std::vector<std::uint64_t> row_index;  // (dart << 32) | row of the orbit being built, hashed
  std::vector<Dart> rows;                // hook j's dart of row r at rows[j * row_count + r]
  std::vector<std::uint32_t> nbr;        // nbr[r * label + k]: row reached from r by hook link k
  std::vector<std::uint32_t> parent;  // parent[r] = p * label + k: r was reached from p by link k
  std::vector<Dart> left;             // left node v's dart of row r at left[v * row_count + r]
  std::vector<Dart> right;            // the same for right nodes
  // update_embedding_slots' lists: FlatLists, whose appends carry no
  // growth path (4 % of the upkeep's instructions as std::vectors).
  FlatList<Dart> orbit;
  FlatList<Dart> marked;
  FlatList<Slot> slots;
  std::vector<Slot> claimed;  // update_embedding_slots' table of the slots kept
  // DartList's buffers: the first dart_lists_open are held by open lists.
  std::vector<std::unique_ptr<std::vector<Dart>>> dart_lists;
  std::size_t dart_lists_open = 0;
};

/// This thread's buffers.
Scratch& scratch();

/// The darts a script's `for each` lists before it runs its statement once
/// per dart. Scripts nest (a statement may apply another script, which lists
/// darts of its own while the outer list is being walked), so one shared
/// buffer would not do: each open list borrows a buffer of this thread's
/// Scratch, in stack order, and gives it back, emptied but with its capacity,
/// when it goes out of scope. A warm rewrite then lists without allocating.
class DartList {
 public:
  DartList();
  ~DartList();
  DartList(const DartList&) = delete;
  DartList& operator=(const DartList&) = delete;

  void push_back(Dart d) { darts_->push_back(d); }
  const Dart* begin() const { return darts_->data(); }
  const Dart* end() const { return darts_->data() + darts_->size(); }
  std::size_t size() const { return darts_->size(); }

 private:
  std::vector<Dart>* darts_;
};

}  // namespace rift::generated
