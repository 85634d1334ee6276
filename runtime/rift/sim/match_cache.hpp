// Matches of one interaction's pattern, one per support orbit, kept in a
// dense array so that a force pass is a flat loop. After a rewrite only the
// support orbits near the touched darts are matched again (§4.1): a match that
// is lost is dropped (its stored forces reset by the caller), a support orbit
// that appears (a split) gets a new match.
//
// Re-matching needs the entry each owner dart holds (owner_index.hpp: 4 bytes
// per dart of the map, or a hash table of the owners where they are few). A
// scene that never rewrites never reads it: it is made at the first rematch,
// from owners_, which build keeps exact, so a 10^6-vertex scene that does not
// tear does not pay 4 bytes per dart per interaction (96 MB for three
// interactions of a quad cloth), and the first tear pays one pass over the
// matches.
// A cache built for a map that is never rewritten (keep_owners(false))
// keeps no owners either: rematch then refuses.
#pragma once

#include <algorithm>
#include <span>
#include <stdexcept>
#include <vector>

#include "rift/core/flat_list.hpp"
#include "rift/core/huge_pages.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/prefetch.hpp"
#include "rift/gmap/gmap.hpp"
#include "rift/sim/owner_index.hpp"
#include "rift/sim/reach.hpp"

namespace rift {

template <class Match>
class MatchCache {
 public:
  static constexpr std::uint32_t kNone = ~0u;

  std::span<const Match> matches() const { return matches_; }
  std::span<Match> matches() { return matches_; }
  std::size_t size() const { return matches_.size(); }
  /// The support dart each match was found from, parallel to matches().
  std::span<const Dart> owners() const { return owners_; }
  /// True once the owners are indexed by dart (from the first rematch on).
  bool indexes_owners() const { return indexed_; }
  /// Before build: false for a map that is never rewritten afterwards; the
  /// owners (4 bytes per match), which only rematch reads, are not kept.
  void keep_owners(bool on) { keeps_owners_ = on; }
  bool keeps_owners() const { return keeps_owners_; }
  /// Gives the matches back, for good: an interaction whose force pass reads
  /// only the groups of identical matches of a map never rewritten
  /// (CachedInteraction) keeps their representatives and counts instead.
  /// matches() is then empty; build fills it again.
  void give_back_matches() {
    if (keeps_owners_) {
      throw std::logic_error("MatchCache: giving back the matches of a cache that can rematch");
    }
    give_back(matches_);
  }
  /// Forces the owner index to a hash table (true) or an array (false)
  /// whatever the share of owners, before the index is made (tests compare
  /// both kinds on the same rewrites).
  void force_sparse_index(bool sparse) { sparse_index_ = sparse ? 1 : 0; }
  /// Whether the owner index is a hash table (owner_index.hpp).
  bool sparse_index() const { return entry_of_.sparse(); }
  /// Indexes the owners now instead of at the first rematch (tests compare
  /// both ways).
  void index_owners(const GMap& map) {
    if (indexed_) return;
    if (!keeps_owners_) {
      throw std::logic_error(
          "MatchCache: re-matching a cache built for a map that is never rewritten");
    }
    if (sparse_index_ < 0) {
      entry_of_.build(owners_, map.capacity());
    } else {
      entry_of_.build(owners_, map.capacity(), sparse_index_ > 0);
    }
    indexed_ = true;
    // rematch's lists, with room for the darts around a tear now (a few
    // hundred), so that tears do not grow them one high-water mark at a
    // time (NoAllocation.WarmTearsAllocateNothing).
    frontier_.reserve(kTearDarts);
    seen_.reserve(kTearDarts);
    found_.reserve(kTearDarts);
  }

  /// Matches every support orbit of the map. match(map, dart, Match&) -> bool.
  template <class MatchFn>
  void build(const GMap& map, Orbit support, MatchFn&& match) {
    build(map, support, match, FirstDart{});
  }

  /// The same, each orbit matched from (and owned by) the dart
  /// choose(map, d) -> Dart picks in d's support orbit. An orbit keeps its
  /// owner afterwards: rematch asks choose only for an orbit without one.
  template <class MatchFn, class ChooseFn>
  void build(const GMap& map, Orbit support, MatchFn&& match, ChooseFn&& choose) {
    start_build(map);
    map.for_each_cell(support, [&](Dart d) { build_from(map, choose(map, d), match); });
  }

  /// build in two halves, for a caller that walks the support orbits itself
  /// (CachedInteraction, during its kernel's inits): start_build empties the
  /// cache, then build_from matches each orbit from its owner, the orbits in
  /// the order of GMap::for_each_cell.
  void start_build(const GMap& map) {
    matches_.clear();
    owners_.clear();
    // At most one match per dart: reserved once (huge pages for a large
    // map), so that building neither moves the arrays nor faults them in
    // page by page; only what the matches fill becomes resident.
    reserve_huge(matches_, map.capacity());
    give_back(owners_);
    if (keeps_owners_) reserve_huge(owners_, map.capacity());
    // Not indexed until a rematch needs it (index_owners); the memory of an
    // earlier index is given back.
    entry_of_.clear();
    indexed_ = false;
  }
  template <class MatchFn>
  void build_from(const GMap& map, Dart owner, MatchFn&& match) {
    Match m{};
    if (match(map, owner, m)) insert(owner, m);
  }

  /// The owner of a support orbit when nothing chooses: the dart at hand.
  struct FirstDart {
    Dart operator()(const GMap& /*map*/, Dart d) const { return d; }
  };

  /// What rematch tells an observer of the dense array (the scatter
  /// colouring), in the order it happens. Entries are indices in matches().
  struct NoObserver {
    /// Entry e is dropped; `last` (the last entry) then takes index e.
    void erased(std::uint32_t /*e*/, std::uint32_t /*last*/) {}
    /// Entry e is matched again: `before` becomes `after`.
    void replaced(std::uint32_t /*e*/, const Match& /*before*/, const Match& /*after*/) {}
    /// A new entry e (the last).
    void inserted(std::uint32_t /*e*/, const Match& /*m*/) {}
  };

  /// Re-matches every support orbit within `radius` links of `region` (the
  /// darts a rewrite touched, live or deleted). lost(const Match&, bool alive)
  /// is called for each match that disappears, before it is dropped, with the
  /// element of matches() itself (its index is its address's offset).
  template <class MatchFn, class LostFn>
  void rematch(const GMap& map, Orbit support, int radius, std::span<const Dart> region,
               MatchFn&& match, LostFn&& lost) {
    NoObserver none;
    rematch(map, support, Reach{radius, {}}, region, match, lost, none);
  }

  /// The same, telling `observer` (a NoObserver's three methods) of every
  /// change of the dense array.
  template <class MatchFn, class LostFn, class Observer>
  void rematch(const GMap& map, Orbit support, const Reach& reach, std::span<const Dart> region,
               MatchFn&& match, LostFn&& lost, Observer& observer) {
    rematch(map, support, reach, region, match, lost, observer, FirstDart{});
  }

  /// The same, a support orbit without an owner (new, or whose owner's match
  /// was lost) matched from the dart choose(map, d) picks (see build).
  template <class MatchFn, class LostFn, class Observer, class ChooseFn>
  void rematch(const GMap& map, Orbit support, const Reach& reach, std::span<const Dart> region,
               MatchFn&& match, LostFn&& lost, Observer& observer, ChooseFn&& choose) {
    index_owners(map);
    entry_of_.cover(map.capacity());
    // Deleted owners first: their matches are gone for good.
    for (Dart d : region) {
      if (map.is_alive(d)) continue;
      const std::uint32_t e = entry_of_.find(d);
      if (e != kNone) {
        lost(matches_[e], false);
        erase(e, observer);
      }
    }
    // The darts whose support orbits may hold a match reading a region dart
    // (reach.hpp), each once.
    const Mark near = map.reserve_mark();
    frontier_.clear();
    auto take = [&](Dart y) {
      if (!map.is_marked(y, near)) {
        map.mark(y, near);
        frontier_.push_back(y);
      }
    };
    if (!reach.words.empty()) {
      // Each word walked back from each live region dart.
      for (Dart d : region) {
        if (!map.is_alive(d)) continue;
        for (const ReachWord& w : reach.words) {
          Dart y = d;
          for (int k = w.length - 1; k >= 0; --k)
            y = map.alpha(y, w.links[static_cast<std::size_t>(k)]);
          take(y);
        }
      }
    } else {
      // Every live dart within `radius` links of the region.
      for (Dart d : region) {
        if (map.is_alive(d)) take(d);
      }
      std::size_t begin = 0;
      for (int step = 0; step < reach.radius; ++step) {
        const std::size_t end = frontier_.size();
        for (std::size_t k = begin; k < end; ++k) {
          for (int i = 0; i <= map.dimension(); ++i)
            take(map.alpha(frontier_[k], i));
        }
        begin = end;
      }
    }
    if (map.capacity() >= kPrefetchFromDarts) prefetch_entries(observer);
    // Each support orbit meeting that neighbourhood: keep one owner, match again.
    const Mark seen = map.reserve_mark();
    seen_.clear();
    for (Dart d : frontier_) {
      if (map.is_marked(d, seen)) continue;
      Dart owner = kNoDart;
      map.for_each_in_orbit(d, support, [&](Dart x) {
        map.mark(x, seen);
        seen_.push_back(x);
        const std::uint32_t e = entry_of_.find(x);
        if (e == kNone) return;
        if (owner == kNoDart) {
          owner = x;
        } else {
          // Two orbits merged (a sew): one match is enough.
          lost(matches_[e], true);
          erase(e, observer);
        }
      });
      const Dart from = owner == kNoDart ? choose(map, d) : owner;
      Match m{};
      const bool matched = match(map, from, m);
      if (owner != kNoDart) {
        const std::uint32_t e = entry_of_.find(owner);
        if (matched) {
          observer.replaced(e, matches_[e], m);
          matches_[e] = m;
        } else {
          lost(matches_[e], true);
          erase(e, observer);
        }
      } else if (matched) {
        insert(from, m);
        observer.inserted(static_cast<std::uint32_t>(matches_.size() - 1), m);
      }
    }
    // Unmarked from the lists of what was marked: walking each frontier
    // dart's support orbit again (a face's eight darts for each of the
    // hundreds of darts near a tear) was a fifth of a tear's instructions.
    for (Dart d : frontier_)
      map.unmark(d, near);
    for (Dart x : seen_)
      map.unmark(x, seen);
    map.free_mark(seen);
    map.free_mark(near);
  }

  /// Its arrays, under `owner` (MemoryReport).
  void report_memory(MemoryReport& report, std::string_view owner) const {
    report.add(owner, "matches", matches_);
    report.add(owner, "match owners (support darts)", owners_);
    entry_of_.report_memory(report, owner);
    report.add(owner, "re-match lists",
               (frontier_.capacity() + seen_.capacity() + found_.capacity()) * sizeof(Dart));
  }

 private:
  // The loop over the neighbourhood's orbits reads, for each, its owner's
  // entry, then that entry's match and what the observer keeps of it: on a
  // large map each read a cache miss, and one after the other they were most
  // of a tear's cost at 10^6 vertices (issue 12, "one tear"). Asked for up
  // front, a level at a time, the misses overlap. Hints only: nothing read
  // here decides anything.
  //
  // Each level reads only what the one before asked for: the owners'
  // entries, then each entry's match, owner and what the observer keeps of
  // it, then its group, then the group's other members (an entry that
  // leaves its group relinks them). An erase also moves the last entry into
  // the hole, reading the last entries' owners and groups: those are asked
  // for too, whether or not the re-match erases (a few lines).
  template <class Observer>
  void prefetch_entries(Observer& observer) {
    for (Dart d : frontier_)
      entry_of_.prefetch_owner(d);
    found_.clear();
    for (Dart d : frontier_) {
      const std::uint32_t e = entry_of_.find(d);
      if (e == kNone) continue;
      found_.push_back(e);
      prefetch(&matches_[e]);
      prefetch(&owners_[e]);
      if constexpr (requires { observer.prefetch_entry(e); }) observer.prefetch_entry(e);
    }
    // The tail: entries [first_last, size).
    const auto first_last =
        static_cast<std::uint32_t>(matches_.size() - std::min(kTailPrefetch, matches_.size()));
    const auto end = static_cast<std::uint32_t>(matches_.size());
    for (std::uint32_t last = first_last; last < end; ++last) {
      prefetch(&matches_[last]);
      prefetch(&owners_[last]);
      if constexpr (requires { observer.prefetch_entry(last); }) observer.prefetch_entry(last);
    }
    if constexpr (requires(std::uint32_t e) { observer.prefetch_group(e); }) {
      for (std::uint32_t e : found_)
        observer.prefetch_group(e);
      for (std::uint32_t last = first_last; last < end; ++last)
        observer.prefetch_group(last);
    }
    for (std::uint32_t last = first_last; last < end; ++last)
      entry_of_.prefetch_owner(owners_[last]);
    if constexpr (requires { observer.prefetch_tail(); }) observer.prefetch_tail();
    if constexpr (requires(std::uint32_t e) { observer.prefetch_members(e); }) {
      for (std::uint32_t e : found_)
        observer.prefetch_members(e);
    }
  }

  void insert(Dart owner, const Match& m) {
    if (indexed_) entry_of_.set(owner, static_cast<std::uint32_t>(matches_.size()));
    // Within the headroom of huge_pages.hpp: a tear appends in place.
    push_back_huge(matches_, m);
    if (keeps_owners_) push_back_huge(owners_, owner);
  }
  // Swap-and-pop keeps the array dense. Only rematch erases: indexed.
  template <class Observer>
  void erase(std::uint32_t e, Observer& observer) {
    const std::uint32_t last = static_cast<std::uint32_t>(matches_.size() - 1);
    observer.erased(e, last);
    entry_of_.erase(owners_[e]);
    if (e != last) {
      matches_[e] = matches_[last];
      owners_[e] = owners_[last];
      entry_of_.set(owners_[e], e);
    }
    matches_.pop_back();
    owners_.pop_back();
  }

  std::vector<Match> matches_;
  std::vector<Dart> owners_;
  OwnerIndex entry_of_;    ///< empty until indexed_
  int sparse_index_ = -1;  ///< -1: as OwnerIndex chooses; 0 / 1: forced (tests)
  bool indexed_ = false;
  bool keeps_owners_ = true;  ///< false: never re-matched, owners_ stays empty
  /// Darts rematch's lists have room for from the first re-match on.
  static constexpr std::size_t kTearDarts = 2048;
  /// The last entries prefetch_entries asks for (erase moves them).
  static constexpr std::size_t kTailPrefetch = 2;
  FlatList<Dart> frontier_;
  FlatList<Dart> seen_;            ///< rematch's darts of the support orbits it walked
  FlatList<std::uint32_t> found_;  ///< prefetch_entries' entries of the frontier
};

}  // namespace rift
