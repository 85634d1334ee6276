// Adapts a generated interaction kernel to the ForceModel interface, with
// its matches cached in a MatchCache. The kernel supplies:
//
//   using Match = ...;                      // trivially copyable: slots and darts
//   static constexpr Orbit kSupport;        // the orbit carrying the parameters
//   static constexpr int kRadius;           // links from the support dart to the farthest matched
//   static constexpr ReachWord kReach[];    // optional: the words to what a match reads
//   (reach.hpp) dart const std::string& name() const; void initialise(GMap&);                 //
//   declare embeddings, compute rest values bool match(const GMap&, Dart, Match&) const; void
//   add_forces(const Match&, const ForceInput&, Vec3* f, bool store); void reset_stored(const
//   Match&);        // zero the stored forces of a lost match Real energy(const Match&, const
//   ForceInput&) const;
//
// The force loop is a flat loop over the cached matches with the kernel
// inlined: no virtual call and no traversal per element.
//
// A kernel with Jacobians (riftc derives them from the rule) also supplies:
//
//   static constexpr int kJacobianVertices;  // vertices per match, k
//   void vertex_slots(const Match&, Slot* out) const;              // k slots
//   void jacobian(const Match&, const ForceInput&, Mat3* dfdx, Mat3* dfdv);  // k² blocks each
//   void jacobian_product(const Match&, const ForceInput&, const Vec3* px,
//                         const Vec3* pv, Vec3* out);  // out += Jx px + Jv pv
//
// A kernel whose rule gives an energy states `static constexpr bool
// kHasEnergy = true;`. It may state `static constexpr bool kJacobianSemidefinite = true;` (the
// rule's `semidefinite;`), and a kernel without them may give `static constexpr const char*
// kJacobianUnavailable` (riftc's located reason).
//
// A kernel that supplies its force targets (riftc emits them)
//
//   static constexpr int kForceTerms;                   // forces per match
//   void force_targets(const Match&, Slot* out) const;  // their vertex slots
//
// scatters in the order of a ScatterColouring (rift/sim/scatter_colouring.hpp):
// blocks of matches coloured so that the blocks of one colour share no
// vertex run in parallel, straight into f, and each vertex receives its
// terms in the same order on any number of threads (one thread included).
//
// A kernel that also gives a group key (riftc emits it for every kernel with forces)
//
//   static constexpr int kGroupKey;                          // words per key
//   void group_key(const Match&, std::uint64_t* out) const;  // vertex slots, then value bits
//   bool evaluate_terms(const Match&, const ForceInput&, Vec3* terms) const;
//   void store_terms(const Match&, const Vec3* terms);       // the stored forces
//   void add_forces_grouped(std::span<const Match> reps, const Real* counts,
//                           const ForceInput&, Vec3* f,      // f += count × forces
//                           Vec3* terms);                    // and each rep's forces
//
// evaluates identical matches once (rift/sim/match_groups.hpp): the
// coloured scatter then runs over groups instead of matches, and a pass that
// stores writes each member's stored forces with the values it would have
// computed itself. Keys compare vertices in order; for two half-edges of one
// edge to give the same order, an untagged kernel's support orbit is matched
// from the dart that binds the smallest vertex slots first (the kernel's
// support_dart), grouped or not. The language lets an untagged interaction
// be matched "from one of the darts" of its support orbit, any of them
// (docs/language.md); the kernel's inits use that same dart, and the orbit
// keeps it for good (MatchCache keeps owners), so a match and its stored
// forces never move to another dart because slots were renumbered.
// (`SimulationSettings::group_interactions` turns grouping off, to compare.)
//
// A kernel may keep the slots only its stored forces are written at apart
// from the match (riftc does), in a trivially copyable `Stored`:
//
//   bool match(const GMap&, Dart, Match&, Stored* s) const;  // fills *s unless null
//   void add_forces_all(std::span<const Match>, const Stored* ss, const ForceInput&,
//                       Vec3* f, bool store);                 // ss parallel to the matches
//   void store_terms(const Match&, const Stored&, const Vec3* terms);
//   void store_group_terms(std::span<const Match>, const Stored* ss, const std::uint32_t* head,
//                          const std::uint32_t* next, const std::uint32_t* groups,
//                          std::size_t n, const Vec3* terms);
//                          // optional: store_terms of every member of groups[i] (i < n),
//                          // walking MatchGroups::member_links, with the terms at
//                          // terms + i × kForceTerms: many groups in one call
//   void reset_stored(const Match&, const Stored&);
//   void set_store_forces(bool);                              // optional, before initialise
//
// The Stored of each match are then kept, parallel to the cache, only when
// the interaction stores (set_store_forces): a stretch spring that stores
// nothing caches 3 slots instead of 5, and its stored-force embedding stays
// unbound (its orbit's attachment may keep no slots at all).
//
// An interaction told that the map is never rewritten (set_rewrites(false),
// a scene without criteria) keeps only what its force passes read: no
// owners in the cache, groups without their keys, table and entries'
// groups (member links only when it stores), a frozen colouring. rematch
// then throws. When it is grouped, stores nothing and nothing asks for its
// Jacobians (set_jacobians_used(false): an explicit integrator), its force
// pass reads only the groups' representatives and counts, so the matches
// themselves are given back too (46 MB for each of the stretch and bending
// springs of a 10^6-vertex cloth), and potential_energy sums count × the
// representative's energy over the groups: the same terms as the sum over
// every match (identical keys, identical arithmetic), added in another
// order, so its last bits may differ from that sum (docs/performance.md,
// "Groups instead of matches when nothing tears"). A tagged kernel is told the map is never
// rewritten too (its set_rewrites): it then keeps no tag, which only
// re-matching reads.
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "rift/core/interrupt.hpp"
#include "rift/core/parallel.hpp"
#include "rift/core/state_embeddings.hpp"
#include "rift/sim/distinct_keys.hpp"
#include "rift/sim/force_model.hpp"
#include "rift/sim/match_cache.hpp"
#include "rift/sim/match_groups.hpp"
#include "rift/sim/scatter_colouring.hpp"
#include "rift/sim/support_sink.hpp"

namespace rift {

namespace detail {
/// The Stored of a kernel that has none (its stored slots are in Match).
struct NoStored {};
template <class Kernel>
auto stored_of() {
  if constexpr (requires { typename Kernel::Stored; }) {
    return typename Kernel::Stored{};
  } else {
    return NoStored{};
  }
}
template <class Kernel>
using StoredOf = decltype(stored_of<Kernel>());
}  // namespace detail

template <class Kernel>
class CachedInteraction final : public ForceModel {
 public:
  template <class... Args>
  explicit CachedInteraction(Args&&... args) : kernel_(std::forward<Args>(args)...) {}

  const std::string& name() const override { return kernel_.name(); }
  Kernel& kernel() { return kernel_; }

  void initialise(GMap& map) override {
    if constexpr (requires(Kernel & k) { k.set_store_forces(true); }) {
      kernel_.set_store_forces(store_forces_);
    }
    if constexpr (requires(Kernel & k) { k.set_rewrites(true); }) {
      kernel_.set_rewrites(rewrites_);
    }
    matches_given_back_ = false;
    matched_ = 0;
    give_back(stored_);
    if (keeps_stored()) reserve_huge(stored_, map.capacity());
    cache_.keep_owners(rewrites_);
    // The cache inserts exactly the matches this returns true for, in order.
    auto match = [&](const GMap& m, Dart d, typename Kernel::Match& out) {
      return kept(match_one(m, d, out));
    };
    if constexpr (requires(GMap & g) { kernel_.initialise(g, SupportSink{}); }) {
      // The inits find every orbit's pattern (support_sink.hpp): the cache
      // takes each match from the darts they found, as they go. A match
      // reads slots, which the inits do not change, never the values they
      // write.
      cache_.start_build(map);
      auto build_from = [&](Dart support, const Dart* darts) {
        cache_.build_from(map, support, [&](const GMap& m, Dart, typename Kernel::Match& out) {
          return kept(match_found_one(m, darts, out));
        });
      };
      kernel_.initialise(map, SupportSink::to(build_from));
    } else {
      kernel_.initialise(map);
      cache_.build(map, Kernel::kSupport, match, support_chooser());
    }
    if constexpr (kGroupable) {
      grouped_ = group_requested_ && Kernel::kGroupKey <= MatchGroups<Match>::kMaxKey;
    }
    // A map that is rewritten gets its owner index now rather than at the
    // first rewrite: that tear then costs what it touches, like every other,
    // not a pass over the whole map (issue 12, deliverable 1).
    if (rewrites_) cache_.index_owners(map);
    if constexpr (kGroupable) {
      if (grouped_) {
        typename MatchGroups<Match>::NoObserver none;
        using Keep = typename MatchGroups<Match>::Keep;
        const Keep keep =
            rewrites_ ? Keep::kEverything : (store_forces_ ? Keep::kMembers : Keep::kCounts);
        // A generated key's first word is a vertex slot (match_groups.hpp).
        const OrbitAttachment* vertices = map.attachment_of(state::kPosition);
        const std::size_t first_words =
            vertices && !vertices->dormant() ? vertices->slot_capacity() : 0;
        // Nothing to share (each element once, e.g. finite elements): the
        // plain pass, without the groups' upkeep. Told apart before building
        // the groups where the keys show it (distinct_keys.hpp), else by the
        // groups built.
        if (keys_all_distinct<Match>(cache_.matches(), Kernel::kGroupKey, key_fn(), first_words)) {
          grouped_ = false;
        } else {
          groups_.build(cache_.matches(), Kernel::kGroupKey, key_fn(), none, keep, first_words);
          grouped_ = groups_.size() < cache_.size();
          if (!grouped_) groups_ = {};
        }
      }
      if (grouped_) {
        const auto reps = groups_.representatives();
        colouring_.build(reps.size(), Kernel::kForceTerms,
                         [&](std::size_t g, Slot* out) { kernel_.force_targets(reps[g], out); });
        if (rewrites_) {
          colouring_.expect_changes();
        } else {
          colouring_.freeze();
        }
        // Nothing reads the matches any more: the pass reads the groups.
        if (!rewrites_ && !store_forces_ && !jacobians_used_) {
          matched_ = cache_.size();
          cache_.give_back_matches();
          matches_given_back_ = true;
        }
        return;
      }
    }
    if constexpr (kColoured) {
      const auto all = cache_.matches();
      colouring_.build(all.size(), Kernel::kForceTerms,
                       [&](std::size_t e, Slot* out) { kernel_.force_targets(all[e], out); });
      if (rewrites_) {
        colouring_.expect_changes();
      } else {
        colouring_.freeze();
      }
    }
  }

  void rematch(const GMap& map, std::span<const Dart> region) override {
    if (!rewrites_) {
      throw std::logic_error("interaction '" + kernel_.name() +
                             "' was set up for a map that is never rewritten (set_rewrites)");
    }
    if constexpr (kAccumulates) {
      if (store_forces_) kernel_.reset_accumulated(map, region);
    }
    // The Stored of the last match is in pending_ until the cache tells
    // the observer what became of it (StoredObserver).
    auto match = [&](const GMap& m, Dart d, typename Kernel::Match& out) {
      return match_one(m, d, out);
    };
    // The cache hands lost matches over in place: their entry is their
    // index in matches().
    auto lost = [&](const typename Kernel::Match& m, bool alive) {
      if (alive && store_forces_) reset_one(m, stored_entry(entry_of(m)));
    };
    if constexpr (kGroupable) {
      if (grouped_) {
        StoredObserver<GroupsObserver> observer{*this, GroupsObserver{*this}};
        cache_.rematch(map, Kernel::kSupport, reach(), region, match, lost, observer,
                       support_chooser());
        return;
      }
    }
    if constexpr (kColoured) {
      StoredObserver<ColouringObserver> observer{*this, ColouringObserver{kernel_, colouring_}};
      cache_.rematch(map, Kernel::kSupport, reach(), region, match, lost, observer,
                     support_chooser());
    } else {
      StoredObserver<typename MatchCache<Match>::NoObserver> observer{*this, {}};
      cache_.rematch(map, Kernel::kSupport, reach(), region, match, lost, observer,
                     support_chooser());
    }
  }

  void clear_accumulated() override {
    if constexpr (kAccumulates) {
      if (store_forces_) kernel_.clear_accumulated();
    }
  }

  void add_forces(const ForceInput& in, Vec3* f, bool store) override {
    store = store && store_forces_;
    if constexpr (kGroupable) {
      if (grouped_) {
        add_forces_grouped(in, f, store);
        return;
      }
    }
    if constexpr (kColoured) {
      add_forces_coloured(in, f, store);
    } else {
      add_forces_in_order(in, f, store);
    }
  }

  /// Before initialise: evaluate identical matches once (the default) or
  /// every match on its own.
  void set_grouping(bool on) override { group_requested_ = on; }
  void set_lanes(bool on) override {
    if constexpr (requires(Kernel & k) { k.set_lanes(true); }) kernel_.set_lanes(on);
  }
  /// Before initialise (which binds the stored embeddings or not).
  void set_store_forces(bool on) override { store_forces_ = on; }
  bool stores_forces() const { return store_forces_; }
  /// Before initialise: false keeps only what the force passes read.
  void set_rewrites(bool on) override { rewrites_ = on; }
  bool rewrites() const { return rewrites_; }
  /// Before initialise: false when nothing asks for Jacobians.
  void set_jacobians_used(bool on) override { jacobians_used_ = on; }
  /// True when only the groups are kept, not every match (see the file comment).
  bool matches_given_back() const { return matches_given_back_; }
  /// True when this interaction's force pass runs over groups.
  bool grouped() const { return grouped_; }
  /// Groups the force pass evaluates (matches when not grouped).
  std::size_t evaluated_matches() const override {
    return grouped_ ? groups_.size() : cache_.size();
  }
  const MatchGroups<typename Kernel::Match>& groups() const { return groups_; }
  /// Checks the groups against the matches (for tests; "" when right).
  std::string check_groups() const {
    if constexpr (kGroupable) {
      if (matches_given_back_) {
        // No matches to check against: the groups must still count them all.
        std::size_t members = 0;
        for (const Real c : groups_.counts())
          members += static_cast<std::size_t>(c);
        return members == matched_ ? "" : "the groups count another number of matches";
      }
      if (grouped_) return groups_.check(cache_.matches(), key_fn());
    }
    return "";
  }

  Real potential_energy(const ForceInput& in) const override {
    Real e = 0;
    if (matches_given_back_) {
      // Each group's members have its representative's energy, bit for bit.
      const std::span<const Match> reps = groups_.representatives();
      const std::span<const Real> counts = groups_.counts();
      for (std::size_t g = 0; g < reps.size(); ++g)
        e += counts[g] * kernel_.energy(reps[g], in);
      return e;
    }
    for (const auto& m : cache_.matches())
      e += kernel_.energy(m, in);
    return e;
  }

  std::size_t active_matches() const override {
    return matches_given_back_ ? matched_ : cache_.size();
  }

  int jacobian_vertices() const override {
    if constexpr (requires { Kernel::kJacobianVertices; }) {
      return Kernel::kJacobianVertices;
    } else {
      return 0;
    }
  }

  bool has_energy() const override {
    if constexpr (requires { Kernel::kHasEnergy; }) {
      return Kernel::kHasEnergy;
    } else {
      return false;
    }
  }

  bool jacobian_semidefinite() const override {
    if constexpr (requires { Kernel::kJacobianSemidefinite; }) {
      return Kernel::kJacobianSemidefinite;
    } else {
      return false;
    }
  }

  std::string jacobian_unavailable_reason() const override {
    if constexpr (requires { Kernel::kJacobianUnavailable; }) {
      return std::string(Kernel::kJacobianUnavailable);
    } else {
      return ForceModel::jacobian_unavailable_reason();
    }
  }

  void jacobians(const ForceInput& in, Slot* slots, Mat3* dfdx, Mat3* dfdv) override {
    if constexpr (requires { Kernel::kJacobianVertices; }) {
      constexpr std::size_t k = Kernel::kJacobianVertices;
      const auto all = cache_.matches();
      // Each match writes its own blocks: parallel without any reduction.
      auto run = [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          kernel_.vertex_slots(all[i], slots + i * k);
          kernel_.jacobian(all[i], in, dfdx + i * k * k, dfdv + i * k * k);
        }
      };
      parallel_blocks(all.size(), kParallelBlock, run);
    }
  }

  void add_jacobian_product(const ForceInput& in, const Vec3* px, const Vec3* pv,
                            Vec3* out) override {
    if constexpr (requires { Kernel::kJacobianVertices; }) {
      for (const auto& m : cache_.matches())
        kernel_.jacobian_product(m, in, px, pv, out);
    }
  }
  const MatchCache<typename Kernel::Match>& cache() const { return cache_; }
  /// The Stored of each match, parallel to cache().matches(); empty when the
  /// interaction does not store or its kernel keeps no such slots apart.
  std::span<const detail::StoredOf<Kernel>> stored() const { return stored_; }
  /// True when stored() holds each match's Stored.
  bool keeps_stored_slots() const { return keeps_stored(); }
  const ScatterColouring& colouring() const { return colouring_; }
  void report_memory(MemoryReport& report) const override {
    const std::string owner = "interaction " + name();
    cache_.report_memory(report, owner);
    report.add(owner, "stored-force slots", stored_);
    groups_.report_memory(report, owner);
    colouring_.report_memory(report, owner);
  }
  /// Matches per block of the coloured scatter; before initialise (tests
  /// use small blocks to have many).
  void set_scatter_block(std::size_t block) { colouring_ = ScatterColouring(block); }

 private:
  using Match = typename Kernel::Match;
  using Stored = detail::StoredOf<Kernel>;
  /// The kernel keeps the slots only stores write apart, in its Stored.
  static constexpr bool kSplitsStored = requires { typename Kernel::Stored; };
  /// ... and has some: they are kept beside the matches when storing.
  static constexpr bool kKeepsStored = kSplitsStored && !std::is_empty_v<Stored>;
  static constexpr bool kHasPass =
      requires(Kernel & k, std::span<const Match> ms, const std::uint32_t* at, std::size_t n,
               const ForceInput& in, Vec3* f) {
    k.add_forces_all(ms, in, f, true);
    k.add_forces_at(ms, at, n, in, f, true);
  }
  || requires(Kernel& k, std::span<const Match> ms, const std::uint32_t* at, std::size_t n,
              const Stored* ss, const ForceInput& in, Vec3* f) {
    k.add_forces_all(ms, ss, in, f, true);
    k.add_forces_at(ms, at, n, ss, in, f, true);
  };
  static constexpr bool kColoured = kHasPass && requires(Kernel & k, const Match& m, Slot* out) {
    Kernel::kForceTerms;
    k.force_targets(m, out);
  };

  bool keeps_stored() const { return kKeepsStored && store_forces_; }
  /// The kernel stores the terms of many groups' members in one call
  /// (riftc's kernels): its columns' storage is then asked for once per
  /// gather, not per member, and the member lists are walked inside it.
  static constexpr bool kStoresGroups =
      requires(Kernel & k, std::span<const Match> ms, const Stored* ss, const std::uint32_t* e,
               std::size_t n, const Vec3* t) {
    k.store_group_terms(ms, ss, e, e, e, n, t);
  };
  bool stores_groups_at_once() const {
    if constexpr (kStoresGroups) {
      return keeps_stored() || !kKeepsStored;  // the kernel reads ss only when it has slots there
    } else {
      return false;
    }
  }

  /// Where a re-match looks (reach.hpp): the kernel's words when it has them.
  static constexpr Reach reach() {
    if constexpr (requires { Kernel::kReach; }) {
      return Reach{Kernel::kRadius, std::span<const ReachWord>(Kernel::kReach)};
    } else {
      return Reach{Kernel::kRadius, {}};
    }
  }

  // The kernel's calls, with or without a Stored.
  /// A build's match: the Stored of a match found is kept beside it.
  bool kept(bool matched) {
    if (matched && keeps_stored()) stored_.push_back(pending_);
    return matched;
  }
  bool match_one(const GMap& map, Dart d, Match& out) {
    if constexpr (kSplitsStored) {
      return kernel_.match(map, d, out, keeps_stored() ? &pending_ : nullptr);
    } else {
      return kernel_.match(map, d, out);
    }
  }
  bool match_found_one(const GMap& map, const Dart* darts, Match& out) {
    if constexpr (kSplitsStored) {
      return kernel_.match_found(map, darts, out, keeps_stored() ? &pending_ : nullptr);
    } else {
      return kernel_.match_found(map, darts, out);
    }
  }
  void reset_one(const Match& m, const Stored& s) {
    if constexpr (kSplitsStored) {
      kernel_.reset_stored(m, s);
    } else {
      kernel_.reset_stored(m);
    }
  }
  void store_one(const Match& m, const Stored& s, const Vec3* terms) {
    if constexpr (kSplitsStored) {
      kernel_.store_terms(m, s, terms);
    } else {
      kernel_.store_terms(m, terms);
    }
  }
  /// The kernel's pass over consecutive matches ms (ss parallel to them)...
  void run_pass(std::span<const Match> ms, const Stored* ss, const ForceInput& in, Vec3* f,
                bool store) {
    if constexpr (kSplitsStored) {
      kernel_.add_forces_all(ms, ss, in, f, store);
    } else {
      kernel_.add_forces_all(ms, in, f, store);
    }
  }
  /// ... and over ms[at[i]] for i < n (ss parallel to ms).
  void run_pass_at(std::span<const Match> ms, const std::uint32_t* at, std::size_t n,
                   const Stored* ss, const ForceInput& in, Vec3* f, bool store) {
    if constexpr (kSplitsStored) {
      kernel_.add_forces_at(ms, at, n, ss, in, f, store);
    } else {
      kernel_.add_forces_at(ms, at, n, in, f, store);
    }
  }
  /// The entry of a match the cache hands over in place.
  std::uint32_t entry_of(const Match& m) const {
    return static_cast<std::uint32_t>(&m - cache_.matches().data());
  }
  Stored stored_entry(std::uint32_t e) const { return keeps_stored() ? stored_[e] : Stored{}; }
  /// The Stored of entries from e on, when kept (a pass that stores reads them).
  const Stored* stored_from(std::size_t e) const {
    return keeps_stored() ? stored_.data() + e : nullptr;
  }

  /// Per-vertex sums (`store +=`), added in the coloured scatter's order.
  static constexpr bool kAccumulates =
      requires(Kernel & k, const GMap& g, std::span<const Dart> region) {
    k.clear_accumulated();
    k.reset_accumulated(g, region);
  };

  static constexpr int terms_per_match() {
    if constexpr (requires { Kernel::kForceTerms; }) {
      return Kernel::kForceTerms;
    } else {
      return 1;
    }
  }
  static constexpr int kTerms = terms_per_match();
  static constexpr bool kGroupable =
      kColoured && requires(const Kernel& k, Kernel& mk, const Match& m, std::uint64_t* key,
                            const ForceInput& in, Vec3* t, std::span<const Match> ms,
                            const Real* counts, const std::uint32_t* at) {
    Kernel::kGroupKey;
    k.group_key(m, key);
    k.evaluate_terms(m, in, t);
    mk.add_forces_grouped(ms, counts, in, t, t);
    mk.add_forces_grouped_at(ms, counts, at, ms.size(), in, t, t);
  }
  &&(
      requires(Kernel& mk, const Match& m, const Vec3* t) { mk.store_terms(m, t); } ||
      requires(Kernel & mk, const Match& m, const Stored& s, const Vec3* t) {
        mk.store_terms(m, s, t);
      });

  auto key_fn() const {
    if constexpr (kGroupable) {
      return [this](const Match& m, std::uint64_t* out) { kernel_.group_key(m, out); };
    } else {
      return [](const Match&, std::uint64_t*) {};
    }
  }

  // The dart a support orbit is matched from when it gets its match: the
  // kernel's choice (riftc's support_dart for an untagged kernel: the dart
  // binding the smallest vertex slots first, which its inits used too), else
  // the dart at hand. Grouped or not, the same dart: grouping changes how
  // matches are evaluated, never which.
  auto support_chooser() const {
    // Two lambdas, not one with an `if constexpr` inside: the second captures
    // nothing (clang rejects an unused `this` capture under -Werror).
    if constexpr (requires(const GMap& map, Dart d) { kernel_.support_dart(map, d); }) {
      return [this](const GMap& map, Dart d) { return kernel_.support_dart(map, d); };
    } else {
      return [](const GMap&, Dart d) { return d; };
    }
  }

  // Follows the match cache's changes in stored_ (the Stored of a match
  // that is matched again or new is the last match's, pending_), then tells
  // `inner`.
  template <class Inner>
  struct StoredObserver {
    CachedInteraction& self;
    Inner inner;
    void erased(std::uint32_t e, std::uint32_t last) {
      inner.erased(e, last);
      if (!self.keeps_stored()) return;
      self.stored_[e] = self.stored_[last];
      self.stored_.pop_back();
    }
    void replaced(std::uint32_t e, const Match& before, const Match& after) {
      inner.replaced(e, before, after);
      if (self.keeps_stored()) self.stored_[e] = self.pending_;
    }
    void inserted(std::uint32_t e, const Match& m) {
      inner.inserted(e, m);
      if (self.keeps_stored()) self.stored_.push_back(self.pending_);
    }
    // MatchCache::rematch's hints (see prefetch_entries there).
    void prefetch_entry(std::uint32_t e) const {
      if (self.keeps_stored()) prefetch(&self.stored_[e]);
      if constexpr (requires { inner.prefetch_entry(e); }) inner.prefetch_entry(e);
    }
    void prefetch_group(std::uint32_t e) const {
      if constexpr (requires { inner.prefetch_group(e); }) inner.prefetch_group(e);
    }
    void prefetch_members(std::uint32_t e) const {
      if constexpr (requires { inner.prefetch_members(e); }) inner.prefetch_members(e);
    }
    void prefetch_tail() const {
      if constexpr (requires { inner.prefetch_tail(); }) inner.prefetch_tail();
    }
  };

  // Follows the match cache's changes in the groups, and the groups' in the colouring.
  struct GroupsObserver {
    CachedInteraction& self;
    struct Colouring {
      CachedInteraction& self;
      void erased(std::uint32_t g, std::uint32_t last) { self.colouring_.erase(g, last); }
      void inserted(std::uint32_t g, const Match& m) {
        Slot s[kTerms];
        self.kernel_.force_targets(m, s);
        self.colouring_.insert(g, s);
      }
    };
    void erased(std::uint32_t e, std::uint32_t last) {
      Colouring c{self};
      self.groups_.erased(e, last, self.cache_.matches(), c);
    }
    void replaced(std::uint32_t e, const Match& before, const Match& after) {
      Colouring c{self};
      self.groups_.replaced(e, before, after, self.cache_.matches(), self.key_fn(), c);
    }
    void inserted(std::uint32_t e, const Match& m) {
      Colouring c{self};
      self.groups_.inserted(e, m, self.key_fn(), c);
    }
    // The colouring is over groups: a group's place is asked for once its
    // id is known (prefetch_group reads the entry's group), its block a
    // level later.
    void prefetch_entry(std::uint32_t e) const { self.groups_.prefetch_entry(e); }
    void prefetch_group(std::uint32_t e) const {
      self.groups_.prefetch_group_of(e);
      if (e < self.cache_.size()) self.colouring_.prefetch_place(self.groups_.group_of(e));
    }
    void prefetch_members(std::uint32_t e) const {
      self.groups_.prefetch_members(e, self.cache_.matches());
      if (e >= self.cache_.size()) return;
      self.colouring_.prefetch_block(self.groups_.group_of(e));
      // replaced() computes the key of e's new match, which mostly reads
      // the values behind the old one's slots.
      if constexpr (requires(const Match& m) { self.kernel_.prefetch_key(m); }) {
        self.kernel_.prefetch_key(self.cache_.matches()[e]);
      }
    }
    // drop_group moves the last group into a dropped one's place.
    void prefetch_tail() const {
      self.groups_.prefetch_last_group();
      if (self.groups_.size() > 0) {
        self.colouring_.prefetch_place(static_cast<std::uint32_t>(self.groups_.size() - 1));
      }
    }
  };

  // The coloured scatter over groups: each group's representative is
  // evaluated once and its forces added count times (count × f: exact for
  // two members, within rounding of the members' sum otherwise, in an order
  // that depends on the groups, never on the threads). A storing pass writes
  // the representative's forces into every member's stored slots: equal
  // keys, equal arithmetic, so the values each member would have stored.
  void add_forces_grouped(const ForceInput& in, Vec3* f, bool store) {
    if constexpr (kGroupable) {
      const std::span<const Match> reps = groups_.representatives();
      const std::span<const Real> counts = groups_.counts();
      const std::span<const Match> all = cache_.matches();
      // A block a tear reshuffled is read in place, through its entries; of
      // a consecutive block only the first entry is read (a frozen colouring
      // keeps no other). A pass that stores runs the same loops kGather
      // groups at a time, which also hand back each group's terms: every
      // member stores them.
      auto body = [&](const std::uint32_t* entries, std::size_t n, bool consecutive) {
        if (n == 0) return;
        // The block's groups from its `first`-th on, `count` of them.
        auto pass = [&](std::size_t first, std::size_t count, Vec3* terms) {
          if (consecutive) {
            const std::size_t g = entries[0] + first;
            kernel_.add_forces_grouped(reps.subspan(g, count), counts.data() + g, in, f, terms);
          } else {
            kernel_.add_forces_grouped_at(reps, counts.data(), entries + first, count, in, f,
                                          terms);
          }
        };
        if (!store) {
          pass(0, n, nullptr);
          return;
        }
        Vec3 terms[kGather * kTerms];     // Eigen leaves it uninitialised
        std::uint32_t gathered[kGather];  // the gather's groups, parallel to its terms
        for (std::size_t first = 0; first < n; first += kGather) {
          const std::size_t count = std::min(kGather, n - first);
          pass(first, count, terms);
          for (std::size_t i = 0; i < count; ++i) {
            gathered[i] = static_cast<std::uint32_t>(consecutive ? entries[0] + first + i
                                                                 : entries[first + i]);
          }
          if (stores_groups_at_once()) {
            if constexpr (kStoresGroups) {
              const auto links = groups_.member_links();
              kernel_.store_group_terms(all, stored_from(0), links.head, links.next, gathered,
                                        count, terms);
            }
          } else {
            for (std::size_t i = 0; i < count; ++i) {
              const Vec3* t = terms + i * kTerms;
              groups_.for_each_member(
                  gathered[i], [&](std::uint32_t e) { store_one(all[e], stored_entry(e), t); });
            }
          }
        }
      };
      colouring_.run(body);
    }
  }

  // Follows the match cache's changes in the colouring.
  struct ColouringObserver {
    Kernel& kernel;
    ScatterColouring& colouring;
    void erased(std::uint32_t e, std::uint32_t last) { colouring.erase(e, last); }
    void replaced(std::uint32_t e, const Match& before, const Match& after) {
      Slot a[Kernel::kForceTerms], b[Kernel::kForceTerms];
      kernel.force_targets(before, a);
      kernel.force_targets(after, b);
      colouring.replace(e, std::equal(a, a + Kernel::kForceTerms, b), b);
    }
    void inserted(std::uint32_t e, const Match& m) {
      Slot s[Kernel::kForceTerms];
      kernel.force_targets(m, s);
      colouring.insert(e, s);
    }
    // MatchCache::prefetch_entries' levels: the colouring's, for entry e.
    void prefetch_entry(std::uint32_t e) const { colouring.prefetch_place(e); }
    void prefetch_group(std::uint32_t e) const { colouring.prefetch_block(e); }
    void prefetch_members(std::uint32_t e) const { colouring.prefetch_block_end(e); }
  };

  void add_forces_coloured(const ForceInput& in, Vec3* f, bool store) {
    const std::span<const Match> all(cache_.matches());
    // A block a tear reshuffled is read in place through its entries.
    auto body = [&](const std::uint32_t* entries, std::size_t n, bool consecutive) {
      if (n == 0) return;
      if (consecutive) {
        run_pass(all.subspan(entries[0], n), stored_from(entries[0]), in, f, store);
      } else {
        run_pass_at(all, entries, n, stored_from(0), in, f, store);
      }
    };
    colouring_.run(body);
  }

  // A kernel without targets: in match order. The pass runs in blocks so that
  // an interrupt is seen within one block (a few thousand matches:
  // microseconds), not one whole pass.
  void add_forces_in_order(const ForceInput& in, Vec3* f, bool store) {
    const std::span<const Match> all(cache_.matches());
    for (std::size_t first = 0; first < all.size(); first += kInterruptBlock) {
      throw_if_interrupted();
      const std::span<const Match> block =
          all.subspan(first, std::min(kInterruptBlock, all.size() - first));
      if constexpr (kHasPass) {
        // Generated kernels run the whole block themselves (columns read once).
        run_pass(block, stored_from(first), in, f, store);
      } else {
        for (const auto& m : block)
          kernel_.add_forces(m, in, f, store);
      }
    }
  }

  static constexpr std::size_t kGather = 64;
  static constexpr std::size_t kInterruptBlock = 4096;
  Kernel kernel_;
  MatchCache<typename Kernel::Match> cache_;
  ScatterColouring colouring_;  ///< the order of the force pass (over groups when grouped_)
  MatchGroups<typename Kernel::Match> groups_;
  /// Each match's Stored, parallel to cache_, when keeps_stored().
  std::vector<Stored> stored_;
  Stored pending_{};  ///< the Stored of the last match found
  bool group_requested_ = true;
  bool grouped_ = false;
  bool store_forces_ = true;         ///< false: nothing reads the stored forces (set_store_forces)
  bool rewrites_ = true;             ///< false: never re-matched (set_rewrites)
  bool jacobians_used_ = true;       ///< false: nothing asks for Jacobians (set_jacobians_used)
  bool matches_given_back_ = false;  ///< only the groups are kept (see the file comment)
  std::size_t matched_ = 0;          ///< the matches there were, when given back
};

}  // namespace rift
