// The generalized map: darts as 32-bit indices, one flat alpha array per
// dimension, marks as per-dart bits, and embeddings attached to orbit types.
//
// Conventions (docs/gmap.md): alpha_i(d) == d means d is i-free; every alpha_i
// is an involution and alpha_i o alpha_j is an involution for i + 2 <= j.
#pragma once

#include <array>
#include <cassert>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "rift/core/orbit.hpp"
#include "rift/core/types.hpp"
#include "rift/embed/attachment.hpp"

namespace rift {

/// Handle to one mark; at most kMaxMarks are reserved at a time.
using Mark = int;

/// How an EmbeddingReader finds a dart's slot: through the attachment's slot
/// array (kSlot), as the dart itself (kDart: an attachment on <>, by dart,
/// attachment.hpp), or either, told at each read (kAny). Generated code knows
/// each embedding's orbit and asks for kSlot or kDart: no test per read.
enum class ReadBy { kAny, kSlot, kDart };

/// Reads of one embedding for a pass that neither adds darts nor gives the
/// column storage (a criterion's collect): the slot and value arrays are
/// taken once, so each read is two plain loads (one by dart) that the
/// compiler may share and reorder. Embedding's own reads check the column's
/// storage with an acquire load each, which keeps the compiler from reusing
/// any address across them. A column without storage reads its default:
/// every slot is masked to 0 and the values point at the default.
template <class T, ReadBy kBy = ReadBy::kAny>
class EmbeddingReader {
 public:
  using value_type = T;
  static constexpr ReadBy kReadBy = kBy;
  EmbeddingReader(const Slot* slots, const T* values, Slot mask)
      : slots_(slots), values_(values), mask_(mask) {}

  const T& operator[](Dart d) const { return values_[slot(d) & mask_]; }
  Slot slot(Dart d) const {
    if constexpr (kBy == ReadBy::kDart) {
      return d;
    } else if constexpr (kBy == ReadBy::kSlot) {
      return slots_[d];
    } else {
      return slots_ ? slots_[d] : d;  // no slot array: by dart
    }
  }

 private:
  const Slot* slots_;
  const T* values_;
  Slot mask_;
};

/// Typed, O(1) access to an embedding: all darts of one orbit read the same value.
template <class T>
class Embedding {
 public:
  using value_type = T;
  Embedding() = default;
  Embedding(OrbitAttachment* attachment, Column<T>* column)
      : attachment_(attachment), column_(column) {}

  explicit operator bool() const { return column_ != nullptr; }
  T& operator[](Dart d) { return column_->values()[attachment_->slot(d)]; }
  /// Reads the default without allocating a withheld column (column.hpp).
  const T& operator[](Dart d) const { return column_->read(attachment_->slot(d)); }
  Slot slot(Dart d) const { return attachment_->slot(d); }
  /// Reads for one pass over an unchanging map (EmbeddingReader); valid
  /// until a dart is created or the column gets storage. kBy kSlot or kDart
  /// must say how the attachment holds its slots (checked here, once).
  template <ReadBy kBy = ReadBy::kAny>
  EmbeddingReader<T, kBy> reader() const {
    if constexpr (kBy != ReadBy::kAny) {
      if (attachment_->by_dart() != (kBy == ReadBy::kDart)) {
        throw std::logic_error("embedding '" + column_->name() + "' on " +
                               attachment_->orbit().str() + " read " +
                               (kBy == ReadBy::kDart ? "by dart" : "by slot"));
      }
    }
    if (const T* values = column_->storage()) return {attachment_->slot_data(), values, ~Slot{0}};
    return {attachment_->slot_data(), &column_->default_value(), 0};
  }
  /// The column's default value (what a reset slot holds).
  const T& default_value() const { return column_->default_value(); }
  /// The dense value array, indexed by slot; dead slots hold stale values.
  std::vector<T>& values() { return column_->values(); }
  const std::vector<T>& values() const { return column_->values(); }
  Orbit orbit() const { return attachment_->orbit(); }
  const OrbitAttachment& attachment() const { return *attachment_; }

 private:
  OrbitAttachment* attachment_ = nullptr;
  Column<T>* column_ = nullptr;
};

class GMap {
 public:
  /// Marks reserved at once, at most: one byte of mark bits per dart. The
  /// deepest nesting of orbit walks in the runtime, the packs' rules,
  /// criteria and scripts and the test suite is 4 (measured); a 32-bit word
  /// per dart was 178 MB of a 4.7·10^7-dart hexahedral block, and the walks
  /// around a tear read the marks at random (rift bench --json, `memory`).
  static constexpr int kMaxMarks = 8;

  explicit GMap(int dimension);
  GMap(GMap&&) noexcept = default;
  GMap& operator=(GMap&&) noexcept = default;
  GMap(const GMap&) = delete;
  GMap& operator=(const GMap&) = delete;

  int dimension() const { return dimension_; }

  /// Which map this is, unique in the process (kept by a move): with
  /// topology_version(), the key of caches derived from the links (CellList).
  std::uint64_t identity() const { return identity_; }
  /// Changes whenever a dart is created, deleted or renumbered or a link is
  /// set or cleared; embeddings and marks do not change it.
  std::uint64_t topology_version() const { return topology_version_; }

  // ---- darts ---------------------------------------------------------------

  /// A new dart, free in every dimension, without embedding values.
  Dart create_dart();
  /// `count` new free darts with consecutive indices; returns the first.
  /// Builders use it to lay out elements without touching the free list.
  Dart create_darts(std::size_t count);
  /// Makes room for `count` more darts without reallocating on each create.
  void reserve(std::size_t count);
  /// Unlinks d in every dimension, releases its embedding slots, and recycles it.
  void delete_dart(Dart d);
  bool is_alive(Dart d) const { return d < alive_.size() && alive_[d]; }
  /// Number of live darts.
  std::size_t size() const { return alive_.size() - free_darts_.size(); }
  /// One past the largest dart index (live or recycled).
  std::size_t capacity() const { return alive_.size(); }

  template <class F>
  void for_each_dart(F&& f) const {
    const std::size_t n = alive_.size();
    for (std::size_t d = 0; d < n; ++d) {
      if (alive_[d]) f(static_cast<Dart>(d));
    }
  }

  // ---- links -----------------------------------------------------------------

  Dart alpha(Dart d, int i) const { return alpha_[i][d]; }
  /// The array of alpha_i, indexed by dart: it moves only when the map
  /// outgrows its headroom (rift/core/huge_pages.hpp; tests check that).
  const Dart* alpha_data(int i) const { return alpha_[i].data(); }
  bool is_free(Dart d, int i) const { return alpha_[i][d] == d; }

  /// Raw link: alpha_i(a) = b and alpha_i(b) = a. No embedding is updated;
  /// builders use this and attach embeddings afterwards. Inline: a mesh's
  /// assembly makes one call per dart and link.
  void link(Dart a, Dart b, int i) {
    assert(is_free(a, i) && is_free(b, i));
    ++topology_version_;
    alpha_[i][a] = b;
    alpha_[i][b] = a;
  }
  /// Raw unlink of a and its i-neighbour.
  void unlink(Dart a, int i);

  /// Why sew(a, b, i) would fail, or an empty string when it can be done.
  std::string why_not_sewable(Dart a, Dart b, int i) const;
  /// G-map i-sew: links the orbit <0..i-2,i+2..n>(a) with the isomorphic
  /// orbit of b, dart by dart. Orbits of embeddings that now merge are merged
  /// with their columns' policies. Returns false and changes nothing when the
  /// sew is impossible (see why_not_sewable).
  bool sew(Dart a, Dart b, int i);
  /// G-map i-unsew of the orbit <0..i-2,i+2..n>(a). An embedding orbit that is
  /// split in two gives each part a copy of the value.
  void unsew(Dart a, int i);

  // ---- marks -----------------------------------------------------------------

  /// Reserves a mark with no marked dart. Throws when all kMaxMarks are taken.
  Mark reserve_mark() const;
  /// Releases a mark; darts still marked with it are unmarked first.
  void free_mark(Mark m) const;
  bool is_marked(Dart d, Mark m) const { return ((mark_bits_[d] >> m) & 1u) != 0; }
  void mark(Dart d, Mark m) const {
    if (!is_marked(d, m)) {
      mark_bits_[d] = static_cast<MarkBits>(mark_bits_[d] | (1u << m));
      ++mark_count_[m];
    }
  }
  void unmark(Dart d, Mark m) const {
    if (is_marked(d, m)) {
      mark_bits_[d] = static_cast<MarkBits>(mark_bits_[d] & ~(1u << m));
      --mark_count_[m];
    }
  }
  std::size_t marked_count(Mark m) const { return mark_count_[m]; }
  /// Unmarks every dart; O(1) when nothing is marked.
  void unmark_all(Mark m) const;
  int reserved_marks() const { return __builtin_popcount(used_marks_); }

  // ---- orbits and cells ------------------------------------------------------

  /// Calls f(dart) once for every dart of the orbit <o>(d). No allocation
  /// after warm-up; f may itself traverse orbits.
  template <class F>
  void for_each_in_orbit(Dart d, Orbit o, F&& f) const;
  /// The walk of for_each_in_orbit on the orbit <i,j>(d) of two links, in
  /// its order, calling f(x, via) with the link `via` (i or j) of the step
  /// that reached x (-1 for d). The walk touches no state of the map.
  template <class F>
  void for_each_in_two_link_orbit(Dart d, int i, int j, F&& f) const;
  /// Marks every dart of <o>(d) with m (darts already marked stop the walk).
  void mark_orbit(Dart d, Orbit o, Mark m) const;
  std::size_t orbit_size(Dart d, Orbit o) const;
  bool in_same_orbit(Dart a, Dart b, Orbit o) const;

  /// Asks for the cache lines a rewrite at `hook` will read: the darts within
  /// `radius` links of it (found level by level, each level's link reads
  /// independent of one another), and for each, its links, flags, marks and
  /// slots of every awake attachment. Only a hint: nothing changes. Does
  /// nothing on a map small enough for the caches (kPrefetchFromDarts).
  /// Generated criteria call it before applying their rule at a candidate.
  void prefetch_around(Dart hook, int radius = kPrefetchRadius) const;
  /// The radius of a tear's prefetch: on the 10^6-vertex cloth, a spring
  /// split read 0.84-0.90x the time with 3, and more with 2 or 4 (fewer
  /// lines asked for, or more than the tear reads).
  static constexpr int kPrefetchRadius = 3;

  /// Calls f(x) with one dart x of each distinct sub-orbit <sub>(x) inside
  /// <o>(d), e.g. each corner <1> of the vertex <1,2>(d).
  template <class F>
  void for_each_sub_orbit(Dart d, Orbit o, Orbit sub, F&& f) const;

  /// Calls f(d) with one dart of each orbit <o> of the map: its smallest
  /// dart, in increasing order of those darts.
  template <class F>
  void for_each_cell(Orbit o, F&& f) const;
  std::size_t count_cells(Orbit o) const;
  /// Cells of dimension k: vertices k = 0, edges 1, faces 2, volumes 3.
  std::size_t count_cells_of_dimension(int k) const;

  // ---- embeddings ----------------------------------------------------------------

  /// Declares an embedding column; existing orbits get the default value.
  /// Throws std::invalid_argument when the name exists or the orbit does not fit.
  template <class T>
  Embedding<T> add_embedding(std::string name, Orbit orbit,
                             MergePolicy policy = MergePolicy::kKeepFirst, T default_value = T{});
  /// Declares an embedding column like add_embedding, without storage for its
  /// values until the first embedding<T>(name): packs declare every embedding
  /// they might use, and a scene pays only for those its components read.
  template <class T>
  void declare_embedding(std::string name, Orbit orbit,
                         MergePolicy policy = MergePolicy::kKeepFirst, T default_value = T{});
  /// Typed access to a declared embedding (empty when there is none); gives
  /// the column its storage if it had none yet, hence not thread-safe.
  template <class T>
  Embedding<T> embedding(std::string_view name) const;
  bool has_embedding(std::string_view name) const { return find_column(name) != nullptr; }
  /// Makes embedding(name) hand out the column without storage until its
  /// first mutable use (column.hpp): for values nothing reads, or that
  /// nothing writes and so read as the default. False when there is no such
  /// column or it already has storage.
  bool withhold_storage(std::string_view name) {
    ColumnBase* c = find_column(name);
    if (!c || c->allocated()) return false;
    c->set_withheld(true);
    return true;
  }
  ColumnBase* find_column(std::string_view name) const;
  /// The attachment holding column `name`; it may be dormant (no slots yet,
  /// attachment.hpp): wake it before reading slots, as embedding() does.
  OrbitAttachment* attachment_of(std::string_view name) const;
  const std::vector<std::unique_ptr<OrbitAttachment>>& attachments() const { return attachments_; }
  /// The map's arrays as "map" (links, marks, lists), then each attachment's
  /// slots and columns (OrbitAttachment::report_memory).
  void report_memory(MemoryReport& report) const;
  /// Gives every orbit of the attachment's type that has no slot a fresh one
  /// (default values), splitting orbits whose darts disagree is not attempted.
  /// A dormant attachment (attachment.hpp) stays so.
  void assign_missing_slots(OrbitAttachment& attachment) const;
  /// Ends the dormancy of an attachment: every orbit gets its slot, numbered
  /// by its smallest dart as at declaration. embedding() calls it: whoever
  /// holds a handle reads slots.
  void wake(OrbitAttachment& attachment) const;
  /// Numbers the orbits of `orbit` from runs of consecutive darts that the
  /// caller knows to be one orbit each: run k is [starts[k], starts[k + 1]),
  /// the last one ending at capacity(), and it takes slot k. A builder knows
  /// this of its elements (each element's darts are made together, and only
  /// the element's own links join them below its dimension), and numbering
  /// them so spares the walk of every orbit: the same slots as that walk
  /// gives (runs in increasing order), without reading a link. Only on a
  /// map whose darts are all alive and hold no slot of `orbit` yet (throws
  /// std::logic_error otherwise); a Debug build checks each run against a walk.
  void number_orbits_by_runs(Orbit orbit, std::span<const Dart> starts);
  /// An awake attachment of orbit o that gives every live dart a slot, or
  /// null (none is awake, or darts made by hand have no slot yet). O(1):
  /// for_each_cell asks it on every call.
  const OrbitAttachment* slotted_attachment(Orbit o) const;

  // ---- validity and maintenance ------------------------------------------------------

  /// Every violated condition, described (empty when valid). At most `limit` entries.
  std::vector<std::string> check_validity(std::size_t limit = 20) const;
  bool is_valid() const { return check_validity(1).empty(); }

  /// In a Debug build (RIFT_CHECK_REWRITES), throws std::logic_error naming
  /// `what` and the violations when the map is invalid; otherwise does
  /// nothing. Called after every sew, unsew and generated rule.
  void check_after_rewrite(const char* what) const;

  /// Renumbers live darts to [0, size()) in order and packs every embedding's
  /// slots. Returns new_index[old] (kNoDart for dead darts). No mark may be reserved.
  std::vector<Dart> compact();

 private:
  /// assign_missing_slots on an awake attachment; `just_woken`: its columns
  /// hold their defaults everywhere (wake grew them from nothing).
  void give_missing_slots(OrbitAttachment& attachment, bool just_woken) const;
  OrbitAttachment& attachment_for(Orbit orbit);
  /// Fills `pairs` (x0, y0, x1, y1, ...) with the darts sew(a, b, i) links;
  /// returns the reason when the two orbits cannot be paired.
  std::string pair_sewing_orbits(Dart a, Dart b, int i, std::vector<Dart>& pairs) const;
  void merge_embeddings_after_sew(const std::vector<Dart>& pairs, int i);
  void split_embeddings_after_unsew(const std::vector<Dart>& pairs, int i);
  std::vector<Dart>& acquire_scratch() const;
  void release_scratch() const { --scratch_depth_; }
  int dimension_;
  std::uint64_t identity_;
  std::uint64_t topology_version_ = 0;
  std::array<std::vector<Dart>, kMaxDimension + 1> alpha_;
  std::vector<std::uint8_t> alive_;
  std::vector<Dart> free_darts_;

  using MarkBits = std::uint8_t;  ///< bit m: marked with mark m
  static_assert(kMaxMarks == 8 * sizeof(MarkBits));
  mutable std::vector<MarkBits> mark_bits_;
  mutable std::array<std::size_t, kMaxMarks> mark_count_{};
  mutable std::uint32_t used_marks_ = 0;

  // Reused traversal buffers, one per nesting depth, so traversals never allocate
  // once warm.
  mutable std::vector<std::unique_ptr<std::vector<Dart>>> scratch_;
  mutable std::size_t scratch_depth_ = 0;
  // partner_[x] during sewing; kNoDart everywhere between calls.
  mutable std::vector<Dart> partner_;
  // prefetch_around: the link that reached each listed dart.
  mutable std::vector<int> via_scratch_;
  // check_validity's per-slot dart counts and first darts, kept between calls.
  mutable std::vector<std::uint32_t> validity_count_;
  mutable std::vector<Dart> validity_first_;

  std::vector<std::unique_ptr<OrbitAttachment>> attachments_;
};

// ---- template implementations ---------------------------------------------------------

template <class F>
void GMap::for_each_in_orbit(Dart d, Orbit o, F&& f) const {
  const int n = o.size();
  if (n == 0) {
    f(d);
    return;
  }
  if (n == 1) {
    const Dart e = alpha_[o.first()][d];
    f(d);
    if (e != d) f(e);
    return;
  }
  if (n == 2) {
    for_each_in_two_link_orbit(d, o.first(), o.second(), [&](Dart x, int) { f(x); });
    return;
  }
  // General orbit: breadth-first walk with a mark; the visit list doubles as queue.
  const Mark m = reserve_mark();
  std::vector<Dart>& visited = acquire_scratch();
  visited.clear();
  visited.push_back(d);
  mark(d, m);
  for (std::size_t k = 0; k < visited.size(); ++k) {
    const Dart x = visited[k];
    for (int i = 0; i <= dimension_; ++i) {
      if (!o.contains(i)) continue;
      const Dart y = alpha_[i][x];
      if (!is_marked(y, m)) {
        mark(y, m);
        visited.push_back(y);
      }
    }
  }
  for (Dart x : visited)
    unmark(x, m);
  free_mark(m);
  // Callbacks run after the walk so that they may change marks freely. The
  // scratch buffer is released even when f throws.
  struct ScratchGuard {
    const GMap& map;
    ~ScratchGuard() { map.release_scratch(); }
  } guard{*this};
  const std::size_t count = visited.size();
  for (std::size_t k = 0; k < count; ++k)
    f(visited[k]);
}

template <class F>
void GMap::for_each_in_two_link_orbit(Dart d, int i, int j, F&& f) const {
  // Darts of a two-link orbit form a path or a cycle alternating i and j.
  const Dart* ai = alpha_[i].data();
  const Dart* aj = alpha_[j].data();
  f(d, -1);
  Dart cur = d;
  bool use_i = true;
  for (;;) {
    const Dart next = use_i ? ai[cur] : aj[cur];
    if (next == cur) break;  // free end: walk the other way from d
    if (next == d) return;   // closed cycle
    f(next, use_i ? i : j);
    cur = next;
    use_i = !use_i;
  }
  cur = d;
  use_i = false;
  for (;;) {
    const Dart next = use_i ? ai[cur] : aj[cur];
    if (next == cur) return;
    f(next, use_i ? i : j);
    cur = next;
    use_i = !use_i;
  }
}

template <class F>
void GMap::for_each_sub_orbit(Dart d, Orbit o, Orbit sub, F&& f) const {
  // The darts of each visited sub-orbit are marked and remembered, and only
  // they are unmarked at the end: a sub-orbit not contained in o spills out
  // of <o>(d), and clearing the mark by a sweep would make a local walk (a
  // tear's script) cost the size of the whole map. The guard also clears the
  // mark when f throws (an interrupt).
  struct MarkGuard {
    const GMap& map;
    Mark m;
    std::vector<Dart>& marked;
    ~MarkGuard() {
      for (Dart x : marked)
        map.unmark(x, m);
      map.free_mark(m);
      map.release_scratch();
    }
  } guard{*this, reserve_mark(), acquire_scratch()};
  guard.marked.clear();
  for_each_in_orbit(d, o, [&](Dart x) {
    if (is_marked(x, guard.m)) return;
    for_each_in_orbit(x, sub, [&](Dart y) {
      mark(y, guard.m);
      guard.marked.push_back(y);
    });
    f(x);
  });
}

template <class F>
void GMap::for_each_cell(Orbit o, F&& f) const {
  const std::size_t n = alive_.size();
  if (const OrbitAttachment* att = slotted_attachment(o)) {
    // Each orbit of a valid map holds one slot of the attachment and no two
    // orbits share one (check_validity): the first dart of each slot met in
    // dart order is its orbit's smallest dart, the dart the marked walk below
    // gives, in the same order. One sequential pass over the slots instead
    // of a walk per orbit over the links and the marks (most of a large
    // set-up's cell passes, and of a criterion's cell list after a tear).
    std::vector<Dart>& seen = acquire_scratch();  // one bit per slot
    struct ScratchGuard {
      const GMap& map;
      ~ScratchGuard() { map.release_scratch(); }
    } guard{*this};
    seen.assign((att->slot_capacity() + 31) / 32, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (!alive_[i]) continue;
      // Read through the attachment: f may add darts, which moves its slots.
      const Slot s = att->slot(static_cast<Dart>(i));
      const Dart bit = Dart{1} << (s % 32);
      if (seen[s / 32] & bit) continue;
      seen[s / 32] |= bit;
      f(static_cast<Dart>(i));
    }
    return;
  }
  // The mark is released even when f throws (an interrupt inside a pass).
  struct MarkGuard {
    const GMap& map;
    Mark m;
    ~MarkGuard() { map.free_mark(m); }
  } guard{*this, reserve_mark()};
  const Mark m = guard.m;
  for (std::size_t i = 0; i < n; ++i) {
    const Dart d = static_cast<Dart>(i);
    if (!alive_[d] || is_marked(d, m)) continue;
    mark_orbit(d, o, m);
    f(d);
  }
}

template <class T>
Embedding<T> GMap::add_embedding(std::string name, Orbit orbit, MergePolicy policy,
                                 T default_value) {
  const std::string key = name;
  declare_embedding<T>(std::move(name), orbit, policy, std::move(default_value));
  return embedding<T>(key);
}

template <class T>
void GMap::declare_embedding(std::string name, Orbit orbit, MergePolicy policy, T default_value) {
  if (find_column(name)) throw std::invalid_argument("embedding '" + name + "' already exists");
  if (!orbit.fits(dimension_)) {
    throw std::invalid_argument("embedding '" + name + "': orbit " + orbit.str() +
                                " does not fit a map of dimension " + std::to_string(dimension_));
  }
  // The attachment stays dormant (no slots) until a column of it is asked for.
  OrbitAttachment& att = attachment_for(orbit);
  att.add_column(std::make_unique<Column<T>>(std::move(name), policy, std::move(default_value)));
  assign_missing_slots(att);
}

template <class T>
Embedding<T> GMap::embedding(std::string_view name) const {
  for (const auto& att : attachments_) {
    if (ColumnBase* c = att->find_column(name)) {
      if (c->type() != ValueTypeOf<T>::value) {
        throw std::invalid_argument("embedding '" + std::string(name) + "' holds " +
                                    std::string(to_string(c->type())) + " values");
      }
      // A withheld column's handle reads slots too: its attachment wakes.
      wake(*att);
      if (!c->withheld()) c->allocate();
      return Embedding<T>(att.get(), static_cast<Column<T>*>(c));
    }
  }
  return {};
}

}  // namespace rift
