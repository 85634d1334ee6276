#include "rift/sim/term_gather.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "rift/core/parallel.hpp"

namespace rift {

void TermGather::build(std::span<const Slot> targets) {
  if (targets.size() >= std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error("TermGather: more than 2^32 terms");
  }
  std::size_t slots = 0;
  for (Slot s : targets) {
    if (s != kNoSlot) slots = std::max<std::size_t>(slots, s + 1);
  }
  offsets_.assign(slots + 1, 0);
  for (Slot s : targets) {
    if (s != kNoSlot) ++offsets_[s + 1];
  }
  for (std::size_t s = 0; s < slots; ++s)
    offsets_[s + 1] += offsets_[s];
  entries_.resize(offsets_[slots]);
  // Filling in term order keeps each slot's entries increasing. The cursor
  // of each slot is its start, moved on; offsets_ is restored after.
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const Slot s = targets[t];
    if (s != kNoSlot) entries_[offsets_[s]++] = static_cast<std::uint32_t>(t);
  }
  for (std::size_t s = slots; s > 0; --s)
    offsets_[s] = offsets_[s - 1];
  offsets_[0] = 0;
}

void TermGather::add_to(const Vec3* terms, Vec3* out) const {
  add_each(out, [terms](std::uint32_t t) -> const Vec3& { return terms[t]; });
}

}  // namespace rift
