// Matches of one interaction that would compute the same forces, grouped so
// that a force pass evaluates each group once (issue 12, deliverable 2).
//
// The paper's springs are atomic: an interior edge of a cloth carries one
// stretch spring per face (two matches of `stretch` on the same two vertices
// with the same stiffness and rest length), and the bending springs repeat
// likewise. A generated kernel gives each match a *key*: the vertex slots
// its body reads and writes forces to, in the pattern's order, then the bits
// of every other value it reads (stiffness, rest length, ...), read through
// the match's own slots. Two matches with equal keys run the same arithmetic
// on the same numbers, so they give the same forces, bit for bit: the group
// evaluates one of them (its representative), adds `count` times each force,
// and stores the same values into every member's stored-force slots, which
// are exactly what each member would have stored on its own. Keys are
// compared in order, never up to a permutation of the vertices: that needs
// no proof of symmetry (see CachedInteraction for how the two half-edges of
// an edge still get the same order).
//
// Groups live in a dense array (the order of the force pass, coloured by
// ScatterColouring like plain matches), members are linked per group, and an
// open-addressing table finds a group from a key. After a tear the groups
// follow the MatchCache's own changes (erased, replaced, inserted), and tell
// an observer of the groups' dense array in turn. Entries are indices in the
// MatchCache's dense array.
//
// What a force pass reads is the representatives and counts; the rest (each
// entry's group, the member links, the keys and the table) is read only to
// follow tears, the member links also by a pass that stores. A build for a
// map that is never rewritten keeps only what its passes read (Keep): at
// 10^6 quads that is 24 of a grouped spring's 136 bytes per group beyond
// the representative (issue 12, lean memory).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "rift/core/huge_pages.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/prefetch.hpp"
#include "rift/core/types.hpp"
#include "rift/embed/value.hpp"

namespace rift {

/// The end of a group's member list (MatchGroups::member_links); generated
/// kernels walk the lists up to it.
inline constexpr std::uint32_t kNoMember = ~0u;

// The words of a key (generated group_key functions write them): a slot as
// it is, a value by its bits, so equal words mean the very same numbers.
inline std::uint64_t* key_words(std::uint32_t slot, std::uint64_t* out) {
  *out = slot;
  return out + 1;
}
inline std::uint64_t* key_words(Real v, std::uint64_t* out) {
  *out = std::bit_cast<std::uint64_t>(v);
  return out + 1;
}
inline std::uint64_t* key_words(std::int64_t v, std::uint64_t* out) {
  *out = static_cast<std::uint64_t>(v);
  return out + 1;
}
inline std::uint64_t* key_words(Bool v, std::uint64_t* out) {
  *out = v.value ? 1 : 0;
  return out + 1;
}
inline std::uint64_t* key_words(const Vec3& v, std::uint64_t* out) {
  for (int i = 0; i < 3; ++i)
    out = key_words(v[i], out);
  return out;
}
inline std::uint64_t* key_words(const Mat3& v, std::uint64_t* out) {
  for (int i = 0; i < 9; ++i)
    out = key_words(v.data()[i], out);
  return out;
}

template <class Match>
class MatchGroups {
 public:
  static constexpr std::uint32_t kNone = kNoMember;
  /// Words per key, at most this many (kernels with longer keys, e.g. a
  /// hexahedron reading 8 vertices and 48 values, are not grouped).
  static constexpr int kMaxKey = 64;
  /// How many matches ahead build computes keys and asks for their table slots.
  static constexpr std::uint32_t kAhead = 16;
  /// How many first matches build reads to size its table (expected_groups).
  static constexpr std::size_t kSample = std::size_t{1} << 16;

  /// What build keeps besides the representatives and their counts.
  enum class Keep {
    kEverything,  ///< what following tears needs (the default)
    kMembers,     ///< the member links only: a pass that stores, never a tear
    kCounts,      ///< nothing more: a pass that never stores, never a tear
  };

  /// What the groups tell an observer (the scatter colouring over groups).
  struct NoObserver {
    /// Group g is dropped; the last group `last` then takes index g.
    void erased(std::uint32_t /*g*/, std::uint32_t /*last*/) {}
    /// A new group g (the last), whose representative is m.
    void inserted(std::uint32_t /*g*/, const Match& /*m*/) {}
  };

  std::size_t size() const { return reps_.size(); }
  /// One member's match per group (any member: they share their key).
  std::span<const Match> representatives() const { return reps_; }
  /// Members per group, parallel to representatives(), as the factor the
  /// force pass multiplies each group's forces by (see count_).
  std::span<const Real> counts() const { return count_; }
  std::uint32_t group_of(std::uint32_t entry) const { return group_of_[entry]; }
  /// Positions of the key table (tests: it is sized for the groups).
  std::size_t table_size() const { return table_.size(); }
  /// What the last build kept.
  Keep keeps() const { return keep_; }
  /// Whether the table still homes keys by their first word (see hash).
  bool homes_by_first_word() const { return by_slot_; }
  /// The member lists as arrays, for a loop that walks many groups' members
  /// (a kernel's store_group_terms): group g's members are e = head[g], then
  /// next[e], until kNone. Valid until the groups change.
  struct MemberLinks {
    const std::uint32_t* head;
    const std::uint32_t* next;
  };
  MemberLinks member_links() const { return {head_.data(), next_.data()}; }
  /// f(entry) for each member of group g (not after a build keeping kCounts).
  template <class F>
  void for_each_member(std::uint32_t g, F&& f) const {
    for (std::uint32_t e = head_[g]; e != kNone; e = next_[e])
      f(e);
  }

  /// Groups `matches` (every entry of the cache). key(const Match&,
  /// std::uint64_t* out) writes `words` words. first_words: the number of
  /// values a key's first word takes (the vertex slots, for generated
  /// kernels), or 0 when unknown; see hash().
  template <class KeyFn, class Observer>
  void build(std::span<const Match> matches, int words, KeyFn&& key, Observer& observer,
             Keep keep = Keep::kEverything, std::size_t first_words = 0) {
    words_ = words;
    keep_ = keep;
    by_slot_ = true;
    reps_.clear();
    count_.clear();
    give_back(head_);
    keys_.clear();
    give_back(group_of_);
    give_back(next_);
    // Filled at once: large ones in huge pages, faulted in on every thread.
    if (keep_ == Keep::kEverything) grow_huge(group_of_, matches.size(), kNone);
    if (keep_ != Keep::kCounts) grow_huge(next_, matches.size(), kNone);
    // Never more groups than matches: reserved once (advised for huge pages),
    // the per-group arrays neither move nor fault in 4 KiB at a time, and
    // only what the groups fill becomes resident (issue 12's set-up).
    reserve_huge(reps_, matches.size());
    reserve_huge(count_, matches.size());
    if (keep_ != Keep::kCounts) reserve_huge(head_, matches.size());
    reserve_huge(keys_, matches.size() * static_cast<std::size_t>(words));
    // Sized for the groups the first matches announce (expected_groups)
    // rather than grown by rehashing; add still grows it for more. Group
    // ids come in order of first match whatever the table's size, so the
    // groups are the same.
    // As many positions per first word as a table for as many groups as
    // matches has for each (the table itself, sized for the groups, is
    // smaller, and the homes wrap around): a vertex that is the first word of many keys (a
    // hexahedral block's vertex heads up to 24 face diagonals, none shared)
    // then keeps its run to itself, however many groups there turn out to be.
    spread_ = first_words == 0 ? kSpread
                               : std::clamp<std::uint64_t>(
                                     std::bit_floor(table_size_for(matches.size()) / first_words),
                                     1, kMaxSpread);
    fresh_table(table_size_for(expected_groups(matches, words, key)));
    // At 10^6 vertices the table and the keys are far larger than the caches
    // and a match's probe reads both at random: nearly all of the grouping's
    // time was those two misses. The keys of the next kAhead matches are
    // computed ahead, their home in the table asked for kAhead matches before
    // it is probed, and the key of the group found there kAhead / 2 before.
    // Hints only: the groups come out as without them.
    const auto n = static_cast<std::uint32_t>(matches.size());
    std::uint64_t ahead[kAhead][kMaxKey];
    std::size_t home[kAhead];
    auto look_ahead = [&](std::uint32_t e) {
      std::uint64_t* k = ahead[e % kAhead];
      key(matches[e], k);
      home[e % kAhead] = hash(k);
      __builtin_prefetch(&table_[home[e % kAhead]]);
    };
    for (std::uint32_t e = 0; e < std::min(n, kAhead); ++e)
      look_ahead(e);
    for (std::uint32_t e = 0; e < n; ++e) {
      if (e + kAhead / 2 < n) {
        // The table may have grown since: a home of the smaller table is
        // still a position of the larger one.
        const std::uint32_t g = table_[home[(e + kAhead / 2) % kAhead]];
        if (g != kNone) __builtin_prefetch(key_of(g));
      }
      add_keyed(e, matches[e], ahead[e % kAhead], observer);
      if (e + kAhead < n) look_ahead(e + kAhead);
    }
    if (keep_ != Keep::kEverything) {
      // Only the tears read them: given back (the build's peak is the
      // representatives, the keys and the table, a few moments).
      give_back(keys_);
      give_back(table_);
    }
  }

  // ---- MatchCache::rematch's events, in its order; `matches` is the cache's
  // dense array at the moment of the event (before the change it announces).

  /// Entry e is dropped and the last entry `last` takes its index.
  template <class Observer>
  void erased(std::uint32_t e, std::uint32_t last, std::span<const Match> matches,
              Observer& observer) {
    require_everything();
    remove(e, matches, observer);
    if (e != last) {
      // Entry `last` becomes e: relink it where it was.
      const std::uint32_t g = group_of_[last];
      group_of_[e] = g;
      next_[e] = next_[last];
      if (head_[g] == last) {
        head_[g] = e;
      } else {
        std::uint32_t p = head_[g];
        while (next_[p] != last)
          p = next_[p];
        next_[p] = e;
      }
    }
    group_of_.pop_back();
    next_.pop_back();
  }

  /// Hints for a caller about to announce changes of entry e (a re-match
  /// of a large map: MatchCache::prefetch_entries): its links, then its
  /// group's key, representative and count. Nothing is read but group_of.
  void prefetch_entry(std::uint32_t e) const {
    if (keep_ != Keep::kEverything || e >= group_of_.size()) return;
    prefetch(&group_of_[e]);
    prefetch(&next_[e]);
  }
  void prefetch_group_of(std::uint32_t e) const {
    if (keep_ != Keep::kEverything || e >= group_of_.size()) return;
    const std::uint32_t g = group_of_[e];
    if (g == kNone) return;
    prefetch(key_of(g));
    prefetch(&reps_[g]);
    prefetch(&count_[g]);
    prefetch(&head_[g]);
  }

  /// Hints for a caller whose entry e may leave its group next (replaced
  /// with another key, erased), after prefetch_group_of: the link and match
  /// of the group's first member, which remove relinks and takes as the
  /// representative, and the group's home in the table, which drop_group
  /// clears. `matches`: the cache's dense array.
  void prefetch_members(std::uint32_t e, std::span<const Match> matches) const {
    if (keep_ != Keep::kEverything || e >= group_of_.size()) return;
    const std::uint32_t g = group_of_[e];
    if (g >= head_.size()) return;
    const std::uint32_t h = head_[g];
    if (h < next_.size()) prefetch(&next_[h]);
    if (h < matches.size()) prefetch(&matches[h]);
    if (!table_.empty()) prefetch(&table_[hash(key_of(g))]);
  }

  /// Hints for drop_group, which moves the last group into the place of
  /// the group it drops: the last group's key, representative, count and
  /// first member.
  void prefetch_last_group() const {
    if (keep_ != Keep::kEverything || reps_.empty()) return;
    const auto last = static_cast<std::uint32_t>(reps_.size() - 1);
    prefetch(key_of(last));
    prefetch(&reps_[last]);
    prefetch(&count_[last]);
    prefetch(&head_[last]);
  }

  /// Entry e is matched again: `before` becomes `after`.
  template <class KeyFn, class Observer>
  void replaced(std::uint32_t e, const Match& before, const Match& after,
                std::span<const Match> matches, KeyFn&& key, Observer& observer) {
    // The group's own copy of its key, not `before`'s: a parameter changed in
    // place (then announced as a rewrite) reads the same from both.
    (void)before;
    require_everything();
    std::uint64_t b[kMaxKey];
    key(after, b);
    if (same_key(b, key_of(group_of_[e]))) {
      // Same group; its representative may have been this entry's old match
      // (whose slots a rewrite may have freed): take the new one.
      reps_[group_of_[e]] = after;
      return;
    }
    remove(e, matches, observer);
    add(e, after, key, observer);
  }

  /// A new entry e (the last), matched as m.
  template <class KeyFn, class Observer>
  void inserted(std::uint32_t e, const Match& m, KeyFn&& key, Observer& observer) {
    require_everything();
    group_of_.push_back(kNone);
    next_.push_back(kNone);
    add(e, m, key, observer);
  }

  /// Checks the groups against the matches as they are now (for tests):
  /// every entry in the group of its key, counts right, no two groups with
  /// one key. Returns an empty string or what is wrong.
  template <class KeyFn>
  std::string check(std::span<const Match> matches, KeyFn&& key) const {
    if (keep_ != Keep::kEverything) return check_kept(matches, key);
    if (group_of_.size() != matches.size()) return "entries and matches differ in number";
    std::vector<std::uint32_t> seen(reps_.size(), 0);
    std::uint64_t a[kMaxKey];
    for (std::uint32_t e = 0; e < matches.size(); ++e) {
      const std::uint32_t g = group_of_[e];
      if (g >= reps_.size()) return "entry " + std::to_string(e) + " has no group";
      ++seen[g];
      key(matches[e], a);
      if (!same_key(a, key_of(g)))
        return "entry " + std::to_string(e) + " is in a group of another key";
    }
    for (std::uint32_t g = 0; g < reps_.size(); ++g) {
      std::uint32_t n = 0;
      for_each_member(g, [&](std::uint32_t e) {
        if (group_of_[e] == g) ++n;
      });
      if (Real(n) != count_[g] || Real(seen[g]) != count_[g])
        return "group " + std::to_string(g) + " has a wrong count";
      key(reps_[g], a);
      if (find(a) != g) return "group " + std::to_string(g) + " is not found by its key";
    }
    return "";
  }

  /// Its arrays, under `owner` (MemoryReport).
  void report_memory(MemoryReport& report, std::string_view owner) const {
    report.add(owner, "group representatives", reps_);
    report.add(owner, "group counts", count_);
    report.add(owner, "group heads", head_);
    report.add(owner, "group keys", keys_);
    report.add(owner, "group of each match", group_of_);
    report.add(owner, "next match of each group", next_);
    report.add(owner, "group table", table_);
  }

 private:
  void require_everything() const {
    if (keep_ != Keep::kEverything) {
      throw std::logic_error(
          "MatchGroups: following a tear with groups built for a map that is never rewritten");
    }
  }

  /// check() of a build that kept less: the groups a fresh grouping of the
  /// matches gives (keys of the representatives, each match counted in the
  /// group of its key), and the member links when kept.
  template <class KeyFn>
  std::string check_kept(std::span<const Match> matches, KeyFn&& key) const {
    std::map<std::vector<std::uint64_t>, std::uint32_t> group_of_key;
    std::uint64_t a[kMaxKey];
    for (std::uint32_t g = 0; g < reps_.size(); ++g) {
      key(reps_[g], a);
      if (!group_of_key.emplace(std::vector<std::uint64_t>(a, a + words_), g).second)
        return "groups " + std::to_string(g) + " and another share a key";
    }
    std::vector<std::uint32_t> seen(reps_.size(), 0);
    for (std::uint32_t e = 0; e < matches.size(); ++e) {
      key(matches[e], a);
      const auto it = group_of_key.find(std::vector<std::uint64_t>(a, a + words_));
      if (it == group_of_key.end()) return "entry " + std::to_string(e) + " has no group";
      ++seen[it->second];
      if (keep_ == Keep::kMembers) {
        bool listed = false;
        for_each_member(it->second, [&](std::uint32_t m) { listed = listed || m == e; });
        if (!listed) return "entry " + std::to_string(e) + " is not a member of its group";
      }
    }
    for (std::uint32_t g = 0; g < reps_.size(); ++g) {
      std::uint32_t n = seen[g];
      if (keep_ == Keep::kMembers) {
        n = 0;
        for_each_member(g, [&](std::uint32_t) { ++n; });
      }
      if (Real(seen[g]) != count_[g] || Real(n) != count_[g])
        return "group " + std::to_string(g) + " has a wrong count";
    }
    return "";
  }

  /// The groups `matches` will form, from the distinct keys of their first
  /// kSample (exact when there are no more), scaled to all of them with a
  /// quarter more: the table is sized for those rather than for half the
  /// matches. A hexahedral block's stretch springs form a group per eight
  /// matches, and its table for half of them was 128 MB where 32 MB do
  /// (rift bench --json, `memory`). The first matches are a mesh's border,
  /// where fewer matches share a key, so the estimate errs high; one short
  /// of the groups only makes add grow the table.
  template <class KeyFn>
  static std::size_t expected_groups(std::span<const Match> matches, int words, KeyFn& key) {
    const std::size_t sample = std::min(matches.size(), kSample);
    std::vector<std::uint64_t> hashes(sample);
    std::uint64_t k[kMaxKey];
    for (std::size_t e = 0; e < sample; ++e) {
      key(matches[e], k);
      hashes[e] = whole_key_hash(k, words);
    }
    std::sort(hashes.begin(), hashes.end());
    const auto distinct =
        static_cast<std::size_t>(std::unique(hashes.begin(), hashes.end()) - hashes.begin());
    if (sample == matches.size()) return distinct;
    const auto scaled =
        static_cast<std::size_t>(static_cast<double>(distinct) *
                                 static_cast<double>(matches.size()) / static_cast<double>(sample));
    return std::min(matches.size(), scaled + scaled / 4);
  }

  /// A hash of all `words` words of a key.
  static std::uint64_t whole_key_hash(const std::uint64_t* k, int words) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int i = 0; i < words; ++i) {
      h ^= k[i] + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 0xbf58476d1ce4e5b9ull;
      h ^= h >> 31;
    }
    return h;
  }

  static std::size_t table_size_for(std::size_t n) {
    std::size_t size = 16;
    while (size < 2 * n + 2)
      size *= 2;
    return size;
  }

  /// A key's home in the table. Keys begin with a vertex slot (generated
  /// kernels write their vertices first), and matches come in the order of
  /// the darts, near which their vertices' slots were given: homed by that
  /// first word (spread_ positions per slot, the rest of the key choosing
  /// within a window of 2^kWindowBits), a build's probes walk the table nearly in
  /// order instead of missing the caches on nearly every match, as a hash
  /// of the whole key did (a quarter of the 10^6 quad cloth's set-up).
  /// A key set whose first words cluster (a vertex in a thousand groups,
  /// or keys whose first word is not a slot) makes long runs: the first
  /// run longer than kLongRun turns this off for the table (by_slot_),
  /// which is then filled again by the hash of the whole key. Where groups
  /// sit in the table never changes which group a key finds, nor the
  /// groups' order.
  std::size_t hash(const std::uint64_t* k) const {
    if (by_slot_) {
      // Within the window only: the other words folded, one multiply (the
      // whole key's chain of multiplies below was most of a build's work
      // once its probes stopped missing the caches).
      std::uint64_t rest = 0;
      for (int i = 1; i < words_; ++i)
        rest ^= k[i] + static_cast<std::uint64_t>(i);
      const std::uint64_t within = (rest * 0x9e3779b97f4a7c15ull) >> (64 - kWindowBits);
      return static_cast<std::size_t>(k[0] * spread_ + within) & (table_.size() - 1);
    }
    return static_cast<std::size_t>(whole_key_hash(k, words_)) & (table_.size() - 1);
  }

  /// Places group g (key k) at the end of its run. False when the run was
  /// longer than kLongRun and the table turned to the hash of the whole key
  /// (refilled with every group, g among them).
  bool place(std::uint32_t g, const std::uint64_t* k) {
    const std::size_t mask = table_.size() - 1;
    std::size_t i = hash(k);
    for (std::size_t run = 0; table_[i] != kNone; ++run) {
      if (by_slot_ && run > kLongRun) {
        by_slot_ = false;
        refill_table(table_.size());
        return false;
      }
      i = (i + 1) & mask;
    }
    table_[i] = g;
    return true;
  }

  const std::uint64_t* key_of(std::uint32_t g) const {
    return keys_.data() + static_cast<std::size_t>(g) * static_cast<std::size_t>(words_);
  }

  /// Keys are a few words: compared in line, word by word (a call to memcmp
  /// per probe was a visible share of the set-up).
  bool same_key(const std::uint64_t* a, const std::uint64_t* b) const {
    for (int i = 0; i < words_; ++i) {
      if (a[i] != b[i]) return false;
    }
    return true;
  }

  /// The group with key k, or kNone.
  std::uint32_t find(const std::uint64_t* k) const {
    for (std::size_t i = hash(k);; i = (i + 1) & (table_.size() - 1)) {
      const std::uint32_t g = table_[i];
      if (g == kNone) return kNone;
      if (same_key(k, key_of(g))) return g;
    }
  }

  /// The table's position holding group g (whose key is k).
  std::size_t position_of(std::uint32_t g, const std::uint64_t* k) const {
    std::size_t i = hash(k);
    while (table_[i] != g)
      i = (i + 1) & (table_.size() - 1);
    return i;
  }

  /// An empty table of `size` positions in a fresh buffer, a large one
  /// advised for huge pages and returned to the system when given back
  /// (16 MB at 10^6 quads: from malloc's heap it stayed resident after the
  /// build gave it back, 40 MB of the quad cloth's peak with three tables).
  void fresh_table(std::size_t size) {
    give_back(table_);
    grow_huge(table_, size, kNone);
  }

  void grow_table() { refill_table(table_size_for(2 * reps_.size())); }

  /// A fresh table of `size` positions holding every group.
  void refill_table(std::size_t size) {
    fresh_table(size);
    for (std::uint32_t g = 0; g < reps_.size(); ++g) {
      if (!place(g, key_of(g))) return;  // refilled by the whole key's hash
    }
  }

  template <class KeyFn, class Observer>
  void add(std::uint32_t e, const Match& m, KeyFn&& key, Observer& observer) {
    std::uint64_t k[kMaxKey];
    key(m, k);
    add_keyed(e, m, k, observer);
  }

  /// add() of a match whose key k is known.
  template <class Observer>
  void add_keyed(std::uint32_t e, const Match& m, const std::uint64_t* k, Observer& observer) {
    std::uint32_t g = find(k);
    if (g == kNone) {
      g = static_cast<std::uint32_t>(reps_.size());
      reps_.push_back(m);
      count_.push_back(0);
      if (keep_ != Keep::kCounts) head_.push_back(kNone);
      keys_.insert(keys_.end(), k, k + words_);
      if (2 * reps_.size() + 2 > table_.size()) {
        grow_table();  // places g too
      } else {
        place(g, k);
      }
      observer.inserted(g, m);
    }
    if (keep_ == Keep::kEverything) group_of_[e] = g;
    if (keep_ != Keep::kCounts) {
      next_[e] = head_[g];
      head_[g] = e;
    }
    ++count_[g];
  }

  /// Takes entry e out of its group; a group left empty is dropped.
  template <class Observer>
  void remove(std::uint32_t e, std::span<const Match> matches, Observer& observer) {
    const std::uint32_t g = group_of_[e];
    if (head_[g] == e) {
      head_[g] = next_[e];
    } else {
      std::uint32_t p = head_[g];
      while (next_[p] != e)
        p = next_[p];
      next_[p] = next_[e];
    }
    group_of_[e] = kNone;
    next_[e] = kNone;
    if (--count_[g] > 0) {
      // The representative may have been e's match: take a remaining member's.
      reps_[g] = matches[head_[g]];
      return;
    }
    drop_group(g, observer);
  }

  template <class Observer>
  void drop_group(std::uint32_t g, Observer& observer) {
    erase_from_table(position_of(g, key_of(g)));
    const std::uint32_t last = static_cast<std::uint32_t>(reps_.size() - 1);
    observer.erased(g, last);
    if (g != last) {
      table_[position_of(last, key_of(last))] = g;
      std::copy(key_of(last), key_of(last) + words_,
                keys_.begin() + static_cast<std::ptrdiff_t>(g) * words_);
      reps_[g] = reps_[last];
      count_[g] = count_[last];
      head_[g] = head_[last];
      for_each_member(g, [&](std::uint32_t m) { group_of_[m] = g; });
    }
    reps_.pop_back();
    count_.pop_back();
    head_.pop_back();
    keys_.resize(keys_.size() - static_cast<std::size_t>(words_));
  }

  /// Linear probing's deletion: later entries of the run move back into
  /// the hole when their home is not after it.
  void erase_from_table(std::size_t hole) {
    const std::size_t mask = table_.size() - 1;
    table_[hole] = kNone;
    for (std::size_t i = (hole + 1) & mask; table_[i] != kNone; i = (i + 1) & mask) {
      const std::size_t home = hash(key_of(table_[i]));
      // Moves back when home is cyclically outside (hole, i].
      const bool between = hole <= i ? (hole < home && home <= i) : (hole < home || home <= i);
      if (!between) {
        table_[hole] = table_[i];
        table_[i] = kNone;
        hole = i;
      }
    }
  }

  /// hash(): positions per value of a key's first word (when build is not
  /// told how many values it takes, and at most), the window the rest of
  /// the key chooses in, the run that turns this off.
  static constexpr std::uint64_t kSpread = 4;
  static constexpr std::uint64_t kMaxSpread = 64;
  static constexpr int kWindowBits = 4;
  static constexpr std::size_t kLongRun = 64;

  int words_ = 0;
  bool by_slot_ = true;             ///< homes by the key's first word (see hash)
  std::uint64_t spread_ = kSpread;  ///< positions per value of a key's first word
  Keep keep_ = Keep::kEverything;
  std::vector<Match> reps_;
  // A whole number kept as a Real: the force pass multiplies every force of
  // a group by it, and converting an integer there (pxor, cvtsi2sd, a
  // register) was 5 % of a spring's evaluation. Exact up to 2^53 members.
  std::vector<Real> count_;
  std::vector<std::uint32_t> head_;      ///< per group: its first member
  std::vector<std::uint64_t> keys_;      ///< per group: its key (words_ words), as grouped
  std::vector<std::uint32_t> group_of_;  ///< per entry
  std::vector<std::uint32_t> next_;      ///< per entry: the next member of its group
  std::vector<std::uint32_t> table_;     ///< open addressing: group ids by key
};

}  // namespace rift
