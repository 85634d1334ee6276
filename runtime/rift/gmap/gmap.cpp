#include "rift/gmap/gmap.hpp"

#include <atomic>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "rift/core/huge_pages.hpp"
#include "rift/core/prefetch.hpp"

namespace rift {

namespace {
std::uint64_t next_identity() {
  static std::atomic<std::uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

/// The involutions of an orbit as raw arrays, looked up once per walk.
struct OrbitLinks {
  std::array<const Dart*, kMaxDimension + 1> arrays{};
  int count = 0;
};

OrbitLinks orbit_links(const std::array<std::vector<Dart>, kMaxDimension + 1>& alpha, int dimension,
                       Orbit o) {
  OrbitLinks l;
  for (int i = 0; i <= dimension; ++i) {
    if (o.contains(i)) l.arrays[static_cast<std::size_t>(l.count++)] = alpha[i].data();
  }
  return l;
}

/// Depth-first walk of the orbit of d (already claimed by the caller) along
/// `links`: claim(y) claims dart y if no one has yet and says whether it did.
/// The walks of set-up use it with their own "visited" state (a mark bit, a
/// slot), without the general walk's visit list and unmarking pass.
template <class Claim>
void flood_orbit(Dart d, const OrbitLinks& links, std::vector<Dart>& stack, Claim&& claim) {
  stack.clear();
  stack.push_back(d);
  while (!stack.empty()) {
    const Dart x = stack.back();
    stack.pop_back();
    for (int l = 0; l < links.count; ++l) {
      const Dart y = links.arrays[static_cast<std::size_t>(l)][x];
      if (claim(y)) stack.push_back(y);
    }
  }
}
/// Whether merging two default values of some column of `att` gives
/// something else (Column::merge's policies applied to the default).
bool merges_away_from_default(const OrbitAttachment& att) {
  for (const auto& column : att.columns()) {
    const MergePolicy policy = column->policy();
    if (policy != MergePolicy::kSum && policy != MergePolicy::kMean) continue;
    if (column->allocated()) return true;  // values to keep, whatever they merge to
    const bool changes = std::visit(
        [&](const auto& value) {
          using T = std::decay_t<decltype(value)>;
          if constexpr (std::is_same_v<T, Bool>) {
            return false;  // a || a == a
          } else if constexpr (std::is_same_v<T, std::int64_t>) {
            const T merged = policy == MergePolicy::kSum ? value + value : (value + value) / 2;
            return merged != value;
          } else {
            const T merged =
                policy == MergePolicy::kSum ? T(value + value) : T((value + value) * Real(0.5));
            return !(merged == value);
          }
        },
        column->get(0));
    if (changes) return true;
  }
  return false;
}
}  // namespace

GMap::GMap(int dimension) : dimension_(dimension), identity_(next_identity()) {
  if (dimension < 1 || dimension > kMaxDimension) {
    throw std::invalid_argument("G-map dimension must be 1, 2 or 3, not " +
                                std::to_string(dimension));
  }
}

// ---- darts ---------------------------------------------------------------------

void GMap::reserve(std::size_t count) {
  // With headroom past `want` (huge_pages.hpp): the rewrites of a tearing
  // map append darts in place rather than copying every dart array.
  const std::size_t want = alive_.size() + count;
  for (int i = 0; i <= dimension_; ++i)
    reserve_huge(alpha_[i], want);
  reserve_huge(alive_, want);
  reserve_huge(mark_bits_, want);
}

Dart GMap::create_dart() {
  ++topology_version_;
  Dart d;
  if (!free_darts_.empty()) {
    d = free_darts_.back();
    free_darts_.pop_back();
    alive_[d] = 1;
    mark_bits_[d] = 0;
  } else {
    if (alive_.size() >= kNoDart) throw std::length_error("G-map: out of 32-bit dart indices");
    d = static_cast<Dart>(alive_.size());
    for (int i = 0; i <= dimension_; ++i)
      push_back_huge(alpha_[i], d);
    push_back_huge(alive_, std::uint8_t{1});
    push_back_huge(mark_bits_, MarkBits{0});
    for (auto& att : attachments_)
      att->resize_darts(alive_.size());
  }
  for (int i = 0; i <= dimension_; ++i)
    alpha_[i][d] = d;
  return d;
}

Dart GMap::create_darts(std::size_t count) {
  ++topology_version_;
  const std::size_t first = alive_.size();
  if (first + count >= kNoDart) throw std::length_error("G-map: out of 32-bit dart indices");
  const std::size_t end = first + count;
  for (int i = 0; i <= dimension_; ++i) {
    grow_huge(alpha_[i], end, Dart{0});
    for (std::size_t d = first; d < end; ++d)
      alpha_[i][d] = static_cast<Dart>(d);
  }
  grow_huge(alive_, end, std::uint8_t{1});
  grow_huge(mark_bits_, end, MarkBits{0});
  for (auto& att : attachments_)
    att->resize_darts(end);
  return static_cast<Dart>(first);
}

void GMap::delete_dart(Dart d) {
  assert(is_alive(d));
  ++topology_version_;
  for (int i = 0; i <= dimension_; ++i)
    unlink(d, i);
  for (auto& att : attachments_)
    att->release(d);
  for (Mark m = 0; m < kMaxMarks; ++m)
    unmark(d, m);
  alive_[d] = 0;
  free_darts_.push_back(d);
}

// ---- links ------------------------------------------------------------------------

void GMap::unlink(Dart a, int i) {
  ++topology_version_;
  const Dart b = alpha_[i][a];
  alpha_[i][a] = a;
  alpha_[i][b] = b;
}

// ---- marks ------------------------------------------------------------------------

Mark GMap::reserve_mark() const {
  if (used_marks_ == (1u << kMaxMarks) - 1) {
    throw std::runtime_error("G-map: all " + std::to_string(kMaxMarks) +
                             " marks are in use (orbit walks nested more deeply than that)");
  }
  const Mark m = __builtin_ctz(~used_marks_);
  used_marks_ |= (1u << m);
  assert(mark_count_[m] == 0);
  return m;
}

void GMap::free_mark(Mark m) const {
  unmark_all(m);
  used_marks_ &= ~(1u << m);
}

void GMap::unmark_all(Mark m) const {
  if (mark_count_[m] == 0) return;
  const auto keep = static_cast<MarkBits>(~(1u << m));
  for (MarkBits& bits : mark_bits_)
    bits &= keep;
  mark_count_[m] = 0;
}

std::vector<Dart>& GMap::acquire_scratch() const {
  if (scratch_depth_ == scratch_.size()) scratch_.push_back(std::make_unique<std::vector<Dart>>());
  return *scratch_[scratch_depth_++];
}

// ---- orbits and cells -----------------------------------------------------------

void GMap::mark_orbit(Dart d, Orbit o, Mark m) const {
  // Every cell pass (for_each_cell) runs this once per cell over the whole
  // map: the links of the orbit are looked up once, and the mark's count is
  // added once at the end rather than per dart.
  const auto bit = static_cast<MarkBits>(1u << m);
  MarkBits* bits = mark_bits_.data();
  std::size_t marked = 0;
  const auto claim = [&](Dart y) {
    if ((bits[y] & bit) != 0) return false;
    bits[y] |= bit;
    ++marked;
    return true;
  };
  if (o.size() <= 2) {
    // A path or a cycle (for_each_in_two_link_orbit), one link, or d alone:
    // no visit list, no stack.
    if (o.size() == 2) {
      for_each_in_two_link_orbit(d, o.first(), o.second(), [&](Dart x, int) { claim(x); });
    } else {
      claim(d);
      if (o.size() == 1) claim(alpha_[o.first()][d]);
    }
    mark_count_[static_cast<std::size_t>(m)] += marked;
    return;
  }
  if (!claim(d)) return;
  flood_orbit(d, orbit_links(alpha_, dimension_, o), acquire_scratch(), claim);
  mark_count_[static_cast<std::size_t>(m)] += marked;
  release_scratch();
}

std::size_t GMap::orbit_size(Dart d, Orbit o) const {
  std::size_t n = 0;
  for_each_in_orbit(d, o, [&](Dart) { ++n; });
  return n;
}

bool GMap::in_same_orbit(Dart a, Dart b, Orbit o) const {
  bool found = false;
  for_each_in_orbit(a, o, [&](Dart x) { found = found || x == b; });
  return found;
}

const OrbitAttachment* GMap::slotted_attachment(Orbit o) const {
  for (const auto& att : attachments_) {
    if (att->orbit() != o || att->dormant()) continue;
    // A valid map gives every live dart a slot; a map being built dart by
    // dart may not have yet (sew and assign_missing_slots fill them in).
    // Only live darts hold slots, so counting them is enough (a pass over
    // every dart here was 3 % of a 10^6-vertex set-up).
    if (att->slotted_darts() == size()) return att.get();
  }
  return nullptr;
}

void GMap::prefetch_around(Dart hook, int radius) const {
  if (capacity() < kPrefetchFromDarts || !is_alive(hook)) return;
  std::vector<Dart>& near = acquire_scratch();
  struct ScratchGuard {
    const GMap& map;
    ~ScratchGuard() { map.release_scratch(); }
  } guard{*this};
  // Each dart with the link that reached it, which is not taken back (an
  // involution would only list its dart again): level k lists at most
  // (n+1) n^(k-1) darts for n+1 links a dart, 4 + 12 + 36 within 3 links of
  // a solid's dart, a few of them twice, which costs a hint more each.
  near.clear();
  std::vector<int>& via = via_scratch_;
  via.clear();
  near.push_back(hook);
  via.push_back(-1);
  std::size_t begin = 0;
  for (int level = 0; level < radius; ++level) {
    const std::size_t end = near.size();
    for (std::size_t k = begin; k < end; ++k) {
      const Dart x = near[k];
      for (int i = 0; i <= dimension_; ++i) {
        if (i == via[k]) continue;
        const Dart y = alpha_[static_cast<std::size_t>(i)][x];
        if (y == x) continue;  // free
        near.push_back(y);
        via.push_back(i);
      }
    }
    begin = end;
  }
  for (const Dart x : near) {
    for (int i = 0; i <= dimension_; ++i)
      prefetch(alpha_[static_cast<std::size_t>(i)].data() + x);
    prefetch(alive_.data() + x);
    prefetch(mark_bits_.data() + x);
    for (const auto& att : attachments_) {
      if (att->dormant()) continue;
      if (const Slot* slots = att->slot_data()) prefetch(slots + x);
    }
  }
}

std::size_t GMap::count_cells(Orbit o) const {
  std::size_t n = 0;
  for_each_cell(o, [&](Dart) { ++n; });
  return n;
}

std::size_t GMap::count_cells_of_dimension(int k) const {
  if (k < 0 || k > dimension_) return 0;
  return count_cells(Orbit::cell(k, dimension_));
}

// ---- embeddings -------------------------------------------------------------------

OrbitAttachment& GMap::attachment_for(Orbit orbit) {
  for (auto& att : attachments_) {
    if (att->orbit() == orbit) return *att;
  }
  attachments_.push_back(std::make_unique<OrbitAttachment>(orbit));
  attachments_.back()->resize_darts(alive_.size());
  return *attachments_.back();
}

ColumnBase* GMap::find_column(std::string_view name) const {
  for (const auto& att : attachments_) {
    if (ColumnBase* c = att->find_column(name)) return c;
  }
  return nullptr;
}

OrbitAttachment* GMap::attachment_of(std::string_view name) const {
  for (const auto& att : attachments_) {
    if (att->find_column(name)) return att.get();
  }
  return nullptr;
}

void GMap::wake(OrbitAttachment& att) const {
  if (!att.dormant()) return;
  att.wake(alive_.size());
  give_missing_slots(att, true);
}

// A fresh attachment (every embedding declared at set-up) has no slot on any
// dart, so an orbit reached for the first time has none on any of its darts:
// the slot array itself can be the walk's visited flag. That saves the mark
// bits (one more per-dart array touched at random) and the unmarking pass of
// the general walk, which together were most of a 10^6-vertex set-up's slot
// assignment (issue 12). Slots are numbered by each orbit's smallest dart, as
// the general walk numbers them, so both give the same slots.
void GMap::assign_missing_slots(OrbitAttachment& att) const {
  const bool woken = att.dormant();
  if (woken) {
    // A sum of two non-zero defaults is not the default: sews and rewrites
    // must merge such a column's values, so its attachment keeps slots from
    // its declaration on.
    if (!merges_away_from_default(att)) return;
    att.wake(alive_.size());
  }
  give_missing_slots(att, woken);
}

void GMap::number_orbits_by_runs(Orbit orbit, std::span<const Dart> starts) {
  OrbitAttachment& att = attachment_for(orbit);
  if (att.by_dart() || (!att.dormant() && att.slotted_darts() != 0) || att.live_slots() != 0 ||
      !free_darts_.empty()) {
    throw std::logic_error("number_orbits_by_runs: orbit " + orbit.str() +
                           " already has slots, or the map has dead darts");
  }
  att.wake(alive_.size());
  att.reserve_slots(att.slot_capacity() + starts.size());
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const Dart end = k + 1 < starts.size() ? starts[k + 1] : static_cast<Dart>(alive_.size());
    if (starts[k] >= end) throw std::logic_error("number_orbits_by_runs: runs out of order");
    const Slot s = att.reserve_slot();
    att.claim_orbit(s, [&](auto&& claim) {
      for (Dart d = starts[k]; d < end; ++d)
        claim(d);
    });
  }
  att.grow_columns();
  if (att.slotted_darts() != size())
    throw std::logic_error("number_orbits_by_runs: the runs do not cover every dart");
#ifndef NDEBUG
  for (std::size_t k = 0; k < starts.size(); ++k) {
    std::size_t in_orbit = 0;
    for_each_in_orbit(starts[k], orbit, [&](Dart x) {
      assert(att.slot(x) == static_cast<Slot>(k));
      ++in_orbit;
    });
    assert(in_orbit == att.darts_in_slot(static_cast<Slot>(k)));
  }
#endif
}

void GMap::give_missing_slots(OrbitAttachment& att, bool just_woken) const {
  // Every live dart holds a slot already (a pack declaring one more column on
  // an awake attachment): nothing to do, and no pass over the darts to find
  // that out (15 such passes were half a second of a 10^6-vertex block's
  // set-up, issue 12). Only live darts hold slots (release), so the count says it.
  if (att.slotted_darts() == size()) return;
  if (att.by_dart()) {
    // Each dart its own slot: no walk, no numbering. Columns just woken
    // hold their defaults everywhere already.
    for (std::size_t k = 0; k < alive_.size(); ++k) {
      if (!alive_[k]) continue;
      if (just_woken) {
        att.hold_as_grown(static_cast<Dart>(k));
      } else {
        att.hold(static_cast<Dart>(k));
      }
    }
    return;
  }
  const Orbit o = att.orbit();
  if (att.live_slots() == 0) {
    // A fresh attachment: each orbit takes the next slot when the sweep in
    // dart order reaches its smallest dart; claim(d, s) gives d's orbit slot s.
    const std::size_t n = alive_.size();
    // At most one orbit per dart: the dart counts are reserved once.
    att.reserve_slots(att.slot_capacity() + n);
    auto number_orbits = [&](auto&& claim) {
      for (std::size_t k = 0; k < n; ++k) {
        const Dart d = static_cast<Dart>(k);
        if (!alive_[d] || att.slot(d) != kNoSlot) continue;
        claim(d, att.reserve_slot());
      }
      att.grow_columns();
    };
    if (o.size() <= 1) {
      // A dart alone (<>) or a dart and its i-neighbour, without a walk.
      const Dart* link = o.size() == 1 ? alpha_[o.first()].data() : nullptr;
      number_orbits([&](Dart d, Slot s) {
        att.claim_orbit(s, [&](auto&& claim) {
          claim(d);
          if (link && link[d] != d) claim(link[d]);
        });
      });
    } else if (o.size() == 2) {
      // A path or a cycle (a vertex of a surface, a face's edge loop): walked
      // along it, without a flood's stack and its second look at each dart.
      number_orbits([&](Dart d, Slot s) {
        att.claim_orbit(s, [&](auto&& claim) {
          for_each_in_two_link_orbit(d, o.first(), o.second(), [&](Dart x, int) { claim(x); });
        });
      });
    } else if (o.size() == 3) {
      // Three links (a solid's vertex <1,2,3>): the orbit is paths or cycles
      // of its first two links (a vertex's corners, one per element) joined
      // by the third. Each is walked along, and only a dart whose third link
      // leads to a dart not numbered yet goes on the stack, rather than
      // every dart with its three links (the flood below: 0.35 s of a
      // 10^6-vertex hexahedral block's set-up).
      const int i = o.first(), j = o.second();
      const Dart* ak = alpha_[o.without(i).without(j).first()].data();
      std::vector<Dart>& stack = acquire_scratch();
      number_orbits([&](Dart d, Slot s) {
        att.claim_orbit(s, [&](auto&& claim) {
          stack.clear();
          stack.push_back(d);
          while (!stack.empty()) {
            const Dart e = stack.back();
            stack.pop_back();
            if (att.slot(e) != kNoSlot) continue;  // its path or cycle is numbered
            for_each_in_two_link_orbit(e, i, j, [&](Dart x, int) {
              claim(x);
              const Dart y = ak[x];
              if (y != x && att.slot(y) == kNoSlot) stack.push_back(y);
            });
          }
        });
      });
      release_scratch();
    } else {
      const OrbitLinks links = orbit_links(alpha_, dimension_, o);
      std::vector<Dart>& stack = acquire_scratch();
      number_orbits([&](Dart d, Slot s) {
        att.claim_orbit(s, [&](auto&& claim) {
          claim(d);
          flood_orbit(d, links, stack, [&](Dart y) {
            if (att.slot(y) != kNoSlot) return false;
            claim(y);
            return true;
          });
        });
      });
      release_scratch();
    }
    return;
  }
  // The columns grow once at the end: growing each of them by one value per
  // new orbit dominated the set-up of large meshes (issue 12).
  for_each_dart([&](Dart d) {
    if (att.slot(d) != kNoSlot) return;
    const Slot s = att.reserve_slot();
    for_each_in_orbit(d, o, [&](Dart x) {
      if (att.slot(x) == kNoSlot) att.assign(x, s);
    });
  });
  att.grow_columns();
}

// ---- validity -------------------------------------------------------------------------

// One flat pass per condition, with no allocation once the scratch arrays
// are warm: messages are formatted only for violations, so the check is cheap
// enough to run after every rewrite (rift run --check) and still complete.
std::vector<std::string> GMap::check_validity(std::size_t limit) const {
  std::vector<std::string> problems;
  auto full = [&] { return problems.size() >= limit; };
  const std::size_t n = alive_.size();

  // Links: every alpha_i is an involution on live darts.
  for (std::size_t k = 0; k < n && !full(); ++k) {
    if (!alive_[k]) continue;
    const Dart d = static_cast<Dart>(k);
    for (int i = 0; i <= dimension_ && !full(); ++i) {
      const Dart e = alpha_[i][d];
      if (e >= n || !alive_[e]) {
        problems.push_back("alpha_" + std::to_string(i) + "(" + std::to_string(d) +
                           ") = " + std::to_string(e) + " is not a live dart");
      } else if (alpha_[i][e] != d) {
        problems.push_back("alpha_" + std::to_string(i) + " is not an involution at dart " +
                           std::to_string(d));
      }
    }
  }
  if (!problems.empty()) return problems;  // the composition test needs sound links

  // alpha_i o alpha_j is an involution for i + 2 <= j.
  for (std::size_t k = 0; k < n && !full(); ++k) {
    if (!alive_[k]) continue;
    const Dart d = static_cast<Dart>(k);
    for (int i = 0; i + 2 <= dimension_; ++i) {
      for (int j = i + 2; j <= dimension_ && !full(); ++j) {
        if (alpha_[j][alpha_[i][alpha_[j][alpha_[i][d]]]] != d) {
          problems.push_back("alpha_" + std::to_string(i) + " o alpha_" + std::to_string(j) +
                             " is not an involution at dart " + std::to_string(d));
        }
      }
    }
  }
  if (!problems.empty()) return problems;

  // Embeddings: every live dart has a slot, constant along its orbit, each
  // slot's dart count is right, and one orbit only holds each slot.
  for (const auto& att : attachments_) {
    if (full()) break;
    if (att->dormant()) continue;  // no slots to check
    const Orbit o = att->orbit();
    if (att->by_dart()) {
      // Each live dart holds its own slot, which no other dart can share.
      for (std::size_t k = 0; k < n && !full(); ++k) {
        if (alive_[k] && att->slot(static_cast<Dart>(k)) == kNoSlot) {
          problems.push_back("embedding on <>: dart " + std::to_string(k) + " has no value");
        }
      }
      if (problems.empty() && att->slotted_darts() != size()) {
        problems.push_back("embedding on <>: counts " + std::to_string(att->slotted_darts()) +
                           " darts with a value, the map has " + std::to_string(size()));
      }
      if (!problems.empty()) break;
      continue;
    }
    const Slot* slot = att->slot_data();
    const std::size_t slots = att->slot_capacity();
    validity_count_.assign(slots, 0);
    validity_first_.assign(slots, kNoDart);
    auto where = [&] { return "embedding on " + o.str() + ": "; };
    for (std::size_t k = 0; k < n && !full(); ++k) {
      if (!alive_[k]) continue;
      const Dart d = static_cast<Dart>(k);
      const Slot s = slot[d];
      if (s == kNoSlot || s >= slots) {
        problems.push_back(where() + "dart " + std::to_string(d) + " has no value");
        continue;
      }
      if (validity_count_[s]++ == 0) validity_first_[s] = d;
      for (int i = 0; i <= dimension_; ++i) {
        if (o.contains(i) && slot[alpha_[i][d]] != s && !full()) {
          problems.push_back(where() + "darts " + std::to_string(d) + " and " +
                             std::to_string(alpha_[i][d]) + " of one orbit hold different values");
        }
      }
    }
    if (!problems.empty()) break;  // the orbit sizes below need constant slots
    if (att->slotted_darts() != size()) {
      // Every live dart has a slot (above): the attachment's count of darts
      // holding one, which slotted_attachment trusts, must say so.
      problems.push_back(where() + "counts " + std::to_string(att->slotted_darts()) +
                         " darts with a value, the map has " + std::to_string(size()));
    }
    for (Slot s = 0; s < slots && !full(); ++s) {
      if (validity_count_[s] != att->darts_in_slot(s)) {
        problems.push_back(where() + "slot " + std::to_string(s) + " is used by " +
                           std::to_string(validity_count_[s]) + " darts but counts " +
                           std::to_string(att->darts_in_slot(s)));
      } else if (validity_count_[s] > 0 &&
                 orbit_size(validity_first_[s], o) != validity_count_[s]) {
        // The orbit of the slot's first dart is constant, hence inside the
        // slot: a slot with more darts holds a second orbit too.
        problems.push_back(where() + "two orbits share slot " + std::to_string(s));
      }
    }
  }
  return problems;
}

void GMap::check_after_rewrite([[maybe_unused]] const char* what) const {
#ifdef RIFT_CHECK_REWRITES
  auto problems = check_validity(5);
  if (!problems.empty()) {
    std::string msg = std::string("G-map invalid after ") + what + ":";
    for (const auto& p : problems)
      msg += "\n  " + p;
    throw std::logic_error(msg);
  }
#endif
}

// ---- compaction -------------------------------------------------------------------------

std::vector<Dart> GMap::compact() {
  if (used_marks_ != 0) throw std::logic_error("G-map: compact() while marks are reserved");
  ++topology_version_;
  const std::size_t n = alive_.size();
  std::vector<Dart> new_index(n, kNoDart);
  Dart next = 0;
  for (std::size_t d = 0; d < n; ++d) {
    if (alive_[d]) new_index[d] = next++;
  }
  for (int i = 0; i <= dimension_; ++i) {
    std::vector<Dart> remapped(next);
    for (std::size_t d = 0; d < n; ++d) {
      if (alive_[d]) remapped[new_index[d]] = new_index[alpha_[i][d]];
    }
    alpha_[i] = std::move(remapped);
  }
  alive_.assign(next, 1);
  mark_bits_.assign(next, 0);
  free_darts_.clear();
  for (auto& att : attachments_) {
    att->remap_darts(new_index, next);
    att->compact_slots();
  }
  return new_index;
}

void GMap::report_memory(MemoryReport& report) const {
  for (std::size_t i = 0; i < alpha_.size(); ++i)
    report.add("map", "alpha" + std::to_string(i) + " links", alpha_[i]);
  report.add("map", "alive flags", alive_);
  report.add("map", "free darts", free_darts_);
  report.add("map", "marks", mark_bits_);
  std::size_t scratch = 0;
  for (const auto& list : scratch_)
    scratch += list->capacity() * sizeof(Dart);  // cleared after use, filled before
  report.add("map", "traversal lists", scratch);
  report.add("map", "sewing partners", partner_);
  report.add("map", "validity counts", validity_count_);
  report.add("map", "validity first darts", validity_first_);
  for (const auto& att : attachments_)
    att->report_memory(report);
}

}  // namespace rift
