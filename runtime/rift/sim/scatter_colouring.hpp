// The order in which a force pass scatters its matches, the same for any
// thread count, with blocks of one colour safe to run at once.
//
// A force pass adds each match's forces to its vertices (f[v] += ...): two
// matches sharing a vertex must not run at once, and for the sums to be the
// same bits on 1 or 8 threads each vertex must receive its terms in an order
// that does not depend on the threads. Here the matches are grouped in blocks
// of block() consecutive matches (a size that depends on nothing but the
// matches), and the blocks are coloured so that two blocks of one colour touch
// no common vertex. A pass runs colour by colour, the blocks of one colour in
// parallel, each block's matches in order, scattering straight into f: a
// vertex receives its terms colour by colour, one block per colour, so in the
// same order whatever the threads (one thread runs the same order too). No
// per-match terms go through memory.
//
// After a tear (MatchCache::rematch) the colouring follows locally: a match
// lost leaves its block, a match whose vertices changed and a new match go
// to a short "pending" list scattered after the colours on one thread, and
// every block() pending matches become a new block with its own colour (a
// colouring of one block holding every match keeps it so instead). Masks
// per vertex (one bit per colour of a block touching it) make colouring a
// block cost its own size; they only ever over-approximate (a block that
// loses a match keeps its bits), which can cost a colour, never a race.
//
// Entries are the indices of the matches in the MatchCache's dense array.
//
// A colouring of matches that never change (a map never rewritten) is
// frozen after its build: it gives back each entry's place and the
// per-vertex masks, which only the changes read, and refuses changes; and
// as every block of a build is consecutive, it keeps each block's first
// entry instead of all of them (the order of a build is the identity).
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "rift/core/huge_pages.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/prefetch.hpp"
#include "rift/core/types.hpp"

namespace rift {

class ScatterColouring {
 public:
  /// Matches per block, by default: n / kTargetBlocks for n matches, at
  /// least kMinBlock. Large blocks meet few others (few colours) and have
  /// few vertices on their border, which each colour's sweep reads again;
  /// 64 blocks leave a few per colour to every thread of a large machine.
  /// The size depends on the matches alone, never on the threads.
  static constexpr std::size_t kMinBlock = 2048;
  static constexpr std::size_t kTargetBlocks = 64;

  /// `block`: matches per block, 0 for the default above (tests use small
  /// blocks to have many).
  explicit ScatterColouring(std::size_t block = 0) : fixed_block_(block) {}
  /// Colours beyond this many: the block runs on one thread after them.
  static constexpr int kMaxColours = 64;

  /// A non-owning reference to `void(const std::uint32_t* entries,
  /// std::size_t count, bool consecutive)`: one block's entries, in order;
  /// `consecutive` when they are entries[0], entries[0] + 1, ..., and then
  /// only entries[0] may be read (a frozen colouring keeps no other).
  class BlockBody {
   public:
    template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, BlockBody>)
        BlockBody(F& f)  // NOLINT(google-explicit-constructor): an argument adaptor
        : object_(static_cast<void*>(&f)),
          call_([](void* o, const std::uint32_t* e, std::size_t n, bool c) {
            (*static_cast<F*>(o))(e, n, c);
          }) {}
    void operator()(const std::uint32_t* e, std::size_t n, bool consecutive) const {
      call_(object_, e, n, consecutive);
    }

   private:
    void* object_;
    void (*call_)(void*, const std::uint32_t*, std::size_t, bool);
  };

  /// Groups entries 0..n-1 in blocks of block() consecutive entries and
  /// colours them. `targets(e, out)` writes the k vertex slots entry e adds
  /// forces to (kNoSlot: none). O(n k).
  template <class Targets>
  void build(std::size_t n, int k, Targets&& targets) {
    begin_build(n, k);
    for (std::size_t first = 0; first < n; first += block_) {
      const std::size_t last = std::min(n, first + block_);
      scratch_.resize((last - first) * k_);
      for (std::size_t e = first; e < last; ++e)
        targets(e, scratch_.data() + (e - first) * k_);
      colour_block(static_cast<std::uint32_t>(first / block_), scratch_);
    }
  }

  /// After build: no change will come; what only changes read is given back.
  void freeze();
  /// After build, for matches that tears will change: the per-vertex mask
  /// gets its headroom now (it was filled piece by piece, its last regrow
  /// may have left it full), so that the vertices tears add extend it in
  /// place and no tear copies it whole. Not in build itself: a colouring
  /// then frozen would have copied its mask for nothing, at the set-up's
  /// memory peak (+26 MB on the 10^6-vertex cloth).
  void expect_changes() { reserve_headroom(mask_); }
  bool frozen() const { return frozen_; }

  /// The matches changed (MatchCache::rematch's events, in its order).
  /// Entry e is dropped and the last entry `last` takes its index.
  void erase(std::uint32_t e, std::uint32_t last);
  /// Entry e keeps its place when its vertices are the same (`same`), else
  /// goes to the pending list (whose vertex slots are `slots`).
  void replace(std::uint32_t e, bool same, std::span<const Slot> slots);
  /// A new entry (the index after the last) with these vertex slots.
  void insert(std::uint32_t e, std::span<const Slot> slots);

  /// Hints for a caller about to change entry e (a re-match of a large map:
  /// MatchCache::prefetch_entries), one level at a time, each reading only
  /// what the one before asked for: e's place, then its block, then the
  /// block's last entry, which remove moves into e's place. Nothing else
  /// is read; a frozen colouring has nothing to ask for.
  void prefetch_place(std::uint32_t e) const {
    if (e < where_.size()) prefetch(&where_[e]);
  }
  void prefetch_block(std::uint32_t e) const {
    if (e >= where_.size()) return;
    const std::uint32_t w = where_[e];
    if ((w & kPendingBit) != 0) return;
    if (w / block_ < blocks_.size()) prefetch(&blocks_[w / block_]);
  }
  void prefetch_block_end(std::uint32_t e) const {
    if (e >= where_.size()) return;
    const std::uint32_t w = where_[e];
    if ((w & kPendingBit) != 0 || w / block_ >= blocks_.size()) return;
    const Block& b = blocks_[w / block_];
    const std::size_t last = w / block_ * block_ + b.size;
    if (b.size > 0 && last - 1 < order_.size()) prefetch(&order_[last - 1]);
  }

  /// Calls body on every block: colour by colour, the blocks of one colour
  /// in parallel (rift/core/parallel.hpp), then the blocks beyond
  /// kMaxColours and the pending entries on the calling thread.
  void run(BlockBody body) const;

  std::size_t block() const { return block_; }
  std::size_t colours() const { return by_colour_.size(); }
  std::size_t blocks() const { return blocks_.size(); }
  std::size_t pending() const { return pending_.size(); }
  std::size_t entries() const { return frozen_ ? frozen_entries_ : where_.size(); }

  /// Checks the colouring against the targets the matches have now (for
  /// tests): every entry in exactly one place, no vertex touched by two
  /// blocks of one colour. Returns an empty string or what is wrong.
  template <class Targets>
  std::string check(std::size_t n, int k, Targets&& targets) const {
    std::vector<Slot> all(n * static_cast<std::size_t>(k));
    for (std::size_t e = 0; e < n; ++e)
      targets(e, all.data() + e * static_cast<std::size_t>(k));
    return check_targets(all, k);
  }

  /// Its arrays, under `owner` (MemoryReport).
  void report_memory(MemoryReport& report, std::string_view owner) const {
    std::size_t lists = serial_.size() * sizeof(std::uint32_t);
    for (const auto& c : by_colour_)
      lists += c.size() * sizeof(std::uint32_t);
    report.add(owner, "colouring blocks", blocks_.size() * sizeof(Block) + lists);
    report.add(owner, "colouring order", order_);
    report.add(owner, "colouring place of each match", where_);
    report.add(owner, "colouring pending matches",
               pending_.size() * sizeof(std::uint32_t) + pending_slots_.size() * sizeof(Slot));
    report.add(owner, "colouring masks", mask_);
  }

 private:
  struct Block {
    std::uint32_t size = 0;
    std::uint16_t colour = 0;  ///< kSerial: beyond kMaxColours
    bool consecutive = true;   ///< its entries are first, first + 1, ...
  };
  static constexpr std::uint16_t kSerial = 0xffff;
  static constexpr std::uint32_t kPendingBit = 0x80000000u;

  /// Blocks of block() consecutive entries, not yet coloured.
  void begin_build(std::size_t n, int k);
  /// Colours block b from the masks of `slots` and records its bits.
  void colour_block(std::uint32_t b, std::span<const Slot> slots);
  /// One block holds every entry, consecutively (see the .cpp): changes
  /// keep it so.
  bool whole_in_one_block() const;
  /// Marks these vertex slots (kNoSlot: none) with a colour's bit.
  void mark(std::span<const Slot> slots, int colour);
  /// Takes e out of its block or the pending list.
  void remove(std::uint32_t e);
  void add_pending(std::uint32_t e, std::span<const Slot> slots);
  /// Every block() pending entries become a block.
  void flush_pending();
  std::string check_targets(std::span<const Slot> targets, int k) const;

  /// Throws when frozen.
  void require_changes() const;

  /// Where block b's entries start in order_.
  std::size_t block_start(std::size_t b) const { return firsts_only_ ? b : b * block_; }
  /// Entry i of block b.
  std::uint32_t entry_of_block(std::size_t b, std::size_t i) const {
    return firsts_only_ ? order_[b] + static_cast<std::uint32_t>(i) : order_[b * block_ + i];
  }

  std::size_t fixed_block_;  ///< 0: chosen by build()
  bool frozen_ = false;
  bool firsts_only_ = false;        ///< frozen, every block consecutive: order_ holds their firsts
  std::size_t frozen_entries_ = 0;  ///< entries() when frozen (where_ is given back)
  std::size_t block_ = kMinBlock;
  std::size_t k_ = 0;
  std::vector<Block> blocks_;
  /// blocks × block(): block b's entries from b·block() (block_start)
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> where_;  ///< per entry: its index in order_, or kPendingBit | index
  std::vector<std::vector<std::uint32_t>> by_colour_;  ///< block ids, increasing
  std::vector<std::uint32_t> serial_;                  ///< blocks beyond kMaxColours
  std::vector<std::uint32_t> pending_;
  std::vector<Slot> pending_slots_;  ///< pending × k: their vertex slots, for colouring
  std::vector<std::uint64_t> mask_;  ///< per vertex slot: colours of blocks touching it
  std::vector<Slot> scratch_;        ///< one block's vertex slots, while colouring it
};

}  // namespace rift
