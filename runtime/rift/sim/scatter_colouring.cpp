#include "rift/sim/scatter_colouring.hpp"

#include <bit>
#include <map>
#include <stdexcept>

#include "rift/core/huge_pages.hpp"
#include "rift/core/interrupt.hpp"
#include "rift/core/parallel.hpp"

namespace rift {

void ScatterColouring::begin_build(std::size_t n, int k) {
  if (n >= kPendingBit) throw std::length_error("ScatterColouring: more than 2^31 matches");
  frozen_ = false;
  firsts_only_ = false;
  frozen_entries_ = 0;
  k_ = static_cast<std::size_t>(k);
  block_ = fixed_block_ != 0 ? fixed_block_
                             : std::max(kMinBlock, (n + kTargetBlocks - 1) / kTargetBlocks);
  const std::size_t blocks = (n + block_ - 1) / block_;
  blocks_.assign(blocks, Block{});
  order_.resize(blocks * block_);
  // Room for the matches tears add, and for a block's worth of pending ones:
  // a tear must not pay for copying arrays of the whole mesh (a
  // reallocation grows them by half at least, so later ones are amortised).
  where_.reserve(n + n / 4 + block_);
  where_.resize(n);
  pending_.reserve(block_);
  pending_slots_.reserve(block_ * k_);
  for (std::size_t e = 0; e < n; ++e) {
    order_[e] = static_cast<std::uint32_t>(e);
    where_[e] = static_cast<std::uint32_t>(e);
  }
  for (std::size_t b = 0; b < blocks; ++b)
    blocks_[b].size = static_cast<std::uint32_t>(std::min(block_, n - b * block_));
  by_colour_.clear();
  serial_.clear();
  pending_.clear();
  pending_slots_.clear();
  mask_.assign(mask_.size(), 0);
}

void ScatterColouring::freeze() {
  // The pending entries (none after a build) stay where they are: run()
  // scatters them last, as before.
  frozen_ = true;
  frozen_entries_ = where_.size();
  // A consecutive block is read from its first entry: keep only those (a
  // build's blocks all are; 4 bytes an entry less, 20 MB of a 10^6 cloth).
  bool consecutive = !firsts_only_;
  for (const Block& b : blocks_)
    consecutive = consecutive && b.consecutive;
  if (consecutive) {
    std::vector<std::uint32_t> firsts(blocks_.size());
    for (std::size_t b = 0; b < blocks_.size(); ++b)
      firsts[b] = order_[b * block_];
    give_back(order_);
    order_ = std::move(firsts);
    firsts_only_ = true;
  }
  give_back(where_);
  give_back(mask_);
  give_back(scratch_);
}

void ScatterColouring::require_changes() const {
  if (frozen_) {
    throw std::logic_error(
        "ScatterColouring: a change of the matches after freeze (a map never rewritten)");
  }
}

void ScatterColouring::mark(std::span<const Slot> slots, int colour) {
  const std::uint64_t bit = std::uint64_t{1} << colour;
  for (Slot v : slots) {
    if (v == kNoSlot) continue;
    if (v >= mask_.size()) grow_huge(mask_, static_cast<std::size_t>(v) + 1, std::uint64_t{0});
    mask_[v] |= bit;
  }
}

void ScatterColouring::colour_block(std::uint32_t b, std::span<const Slot> slots) {
  std::uint64_t used = 0;
  for (Slot v : slots) {
    if (v == kNoSlot) continue;
    if (v >= mask_.size()) grow_huge(mask_, static_cast<std::size_t>(v) + 1, std::uint64_t{0});
    used |= mask_[v];
  }
  if (~used == 0) {
    blocks_[b].colour = kSerial;
    serial_.push_back(b);
    return;
  }
  const int c = std::countr_zero(~used);
  mark(slots, c);
  blocks_[b].colour = static_cast<std::uint16_t>(c);
  if (static_cast<std::size_t>(c) >= by_colour_.size()) by_colour_.resize(c + 1);
  by_colour_[c].push_back(b);  // blocks are coloured in increasing order
}

void ScatterColouring::remove(std::uint32_t e) {
  const std::uint32_t w = where_[e];
  if ((w & kPendingBit) != 0) {
    const std::uint32_t i = w & ~kPendingBit;
    const std::size_t last = pending_.size() - 1;
    if (i != last) {
      pending_[i] = pending_[last];
      std::copy_n(pending_slots_.begin() + static_cast<std::ptrdiff_t>(last * k_), k_,
                  pending_slots_.begin() + static_cast<std::ptrdiff_t>(i * k_));
      where_[pending_[i]] = kPendingBit | i;
    }
    pending_.pop_back();
    pending_slots_.resize(pending_.size() * k_);
    return;
  }
  Block& b = blocks_[w / block_];
  const std::uint32_t last = static_cast<std::uint32_t>(w / block_ * block_) + b.size - 1;
  if (w != last) {
    order_[w] = order_[last];
    where_[order_[w]] = w;
    b.consecutive = false;
  }
  --b.size;
}

// A colouring of one block that holds every entry, in order (a small map:
// at most block() matches), stays so through changes, at a cost independent
// of the block's size: an erased entry's place is taken by the last one,
// which leaves the block 0 .. n-2; a replaced entry keeps its place, its new
// vertices marked with the block's colour (for the blocks a growth past
// block() would add); a new entry joins the block while it has room. The
// block then runs consecutively, the kernels' fast path, instead of in place
// with a pending list after it; one block runs on one thread, so the sums
// stay independent of the thread count.
bool ScatterColouring::whole_in_one_block() const {
  return blocks_.size() == 1 && pending_.empty() && blocks_[0].consecutive &&
         blocks_[0].size == where_.size() && blocks_[0].colour != kSerial;
}

void ScatterColouring::erase(std::uint32_t e, std::uint32_t last) {
  require_changes();
  if (whole_in_one_block()) {
    --blocks_[0].size;
    where_.pop_back();
    return;
  }
  remove(e);
  if (e != last) {
    const std::uint32_t w = where_[last];
    where_[e] = w;
    if ((w & kPendingBit) != 0) {
      pending_[w & ~kPendingBit] = e;
    } else {
      order_[w] = e;
      blocks_[w / block_].consecutive = false;
    }
  }
  where_.pop_back();
}

void ScatterColouring::replace(std::uint32_t e, bool same, std::span<const Slot> slots) {
  require_changes();
  if (same) return;
  if (whole_in_one_block()) {
    mark(slots, blocks_[0].colour);
    return;
  }
  remove(e);
  add_pending(e, slots);
}

void ScatterColouring::insert(std::uint32_t e, std::span<const Slot> slots) {
  require_changes();
  if (e != where_.size()) throw std::logic_error("ScatterColouring::insert: not the next entry");
  if (whole_in_one_block() && blocks_[0].size < block_) {
    order_[e] = e;
    where_.push_back(e);
    ++blocks_[0].size;
    mark(slots, blocks_[0].colour);
    return;
  }
  where_.push_back(0);
  add_pending(e, slots);
}

void ScatterColouring::add_pending(std::uint32_t e, std::span<const Slot> slots) {
  where_[e] = kPendingBit | static_cast<std::uint32_t>(pending_.size());
  pending_.push_back(e);
  pending_slots_.insert(pending_slots_.end(), slots.begin(), slots.end());
  if (pending_.size() >= block_) flush_pending();
}

void ScatterColouring::flush_pending() {
  const auto b = static_cast<std::uint32_t>(blocks_.size());
  const std::size_t first = order_.size();
  blocks_.push_back(Block{static_cast<std::uint32_t>(pending_.size()), 0, true});
  order_.resize(first + block_);
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    order_[first + i] = pending_[i];
    where_[pending_[i]] = static_cast<std::uint32_t>(first + i);
    if (pending_[i] != pending_[0] + i) blocks_[b].consecutive = false;
  }
  colour_block(b, pending_slots_);
  pending_.clear();
  pending_slots_.clear();
}

void ScatterColouring::run(BlockBody body) const {
  for (const std::vector<std::uint32_t>& list : by_colour_) {
    auto pass = [&](std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i) {
        throw_if_interrupted();
        const Block& b = blocks_[list[i]];
        body(order_.data() + block_start(list[i]), b.size, b.consecutive);
      }
    };
    parallel_blocks(list.size(), 1, pass);
  }
  for (std::uint32_t id : serial_) {
    throw_if_interrupted();
    body(order_.data() + block_start(id), blocks_[id].size, blocks_[id].consecutive);
  }
  if (!pending_.empty()) body(pending_.data(), pending_.size(), false);
}

std::string ScatterColouring::check_targets(std::span<const Slot> targets, int k) const {
  const std::size_t n = targets.size() / static_cast<std::size_t>(k);
  if (entries() != n)
    return "the colouring has " + std::to_string(entries()) + " entries, the matches " +
           std::to_string(n);
  std::vector<int> seen(n, 0);
  // Per colour, the block touching each vertex.
  std::vector<std::map<Slot, std::uint32_t>> owner(by_colour_.size());
  for (std::uint32_t id = 0; id < blocks_.size(); ++id) {
    const Block& b = blocks_[id];
    for (std::uint32_t i = 0; i < b.size; ++i) {
      const std::uint32_t e = entry_of_block(id, i);
      if (e >= n) return "block " + std::to_string(id) + " holds entry " + std::to_string(e);
      ++seen[e];
      if (!frozen_ && where_[e] != id * block_ + i)
        return "where_ of entry " + std::to_string(e) + " is stale";
      if (b.consecutive && e != entry_of_block(id, 0) + i)
        return "block " + std::to_string(id) + " is not consecutive";
      if (b.colour == kSerial) continue;
      for (int j = 0; j < k; ++j) {
        const Slot v = targets[e * static_cast<std::size_t>(k) + j];
        if (v == kNoSlot) continue;
        const auto [it, fresh] = owner[b.colour].emplace(v, id);
        if (!fresh && it->second != id)
          return "vertex " + std::to_string(v) + " is touched by blocks " +
                 std::to_string(it->second) + " and " + std::to_string(id) + " of colour " +
                 std::to_string(b.colour);
      }
    }
  }
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    ++seen[pending_[i]];
    if (!frozen_ && where_[pending_[i]] != (kPendingBit | i))
      return "where_ of a pending entry is stale";
    for (std::size_t j = 0; j < k_; ++j) {
      if (pending_slots_[i * k_ + j] != targets[pending_[i] * k_ + j])
        return "the vertices of pending entry " + std::to_string(pending_[i]) + " are stale";
    }
  }
  for (std::size_t e = 0; e < n; ++e) {
    if (seen[e] != 1)
      return "entry " + std::to_string(e) + " is held " + std::to_string(seen[e]) + " times";
  }
  return "";
}

}  // namespace rift
