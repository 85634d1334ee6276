#include "emit/prelude.hpp"

namespace rift::emit {

std::string_view prelude() {
  return R"RIFT(namespace {

constexpr std::uint32_t kNoRow = 0xFFFFFFFFu;

/// Buffers reused by every rule of the pack: after warm-up, matching does not allocate.
struct Scratch {
  std::vector<std::uint32_t> row_of;  // by dart, kNoRow outside the orbit being built
  std::vector<rift::Dart> rows;       // hook j's dart of row r at rows[j * row_count + r]
  std::vector<std::uint32_t> nbr;     // nbr[r * label + k]: row reached from r by hook link k
  std::vector<std::uint32_t> parent;  // parent[r] = p * label + k: r was reached from p by link k
  std::vector<rift::Dart> left;       // left node v's dart of row r at left[v * row_count + r]
  std::vector<rift::Dart> right;      // the same for right nodes
  std::vector<rift::Dart> orbit;
  std::vector<rift::Dart> marked;
  std::vector<rift::Slot> slots;
  std::vector<rift::Slot> claimed;
  std::vector<rift::Slot> seen;
};

[[maybe_unused]] Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

/// The rows of a match: the darts of the hook orbit <H>(hooks[0]) in breadth-first order,
/// and the same walk from every other hook, which must meet an isomorphic orbit (Jerboa's
/// condition for rules with several hooks).
[[maybe_unused]] bool build_rows(const rift::GMap& g, const rift::Dart* hooks, std::size_t hook_count,
                const int* hook_dims, std::size_t label, Scratch& s, std::size_t& row_count) {
  if (s.row_of.size() < g.capacity()) s.row_of.resize(g.capacity(), kNoRow);
  s.rows.clear();
  s.nbr.clear();
  s.parent.clear();
  if (hook_count == 0) {
    row_count = 1;  // a generator: one row, nothing matched
    return true;
  }
  s.rows.push_back(hooks[0]);
  s.parent.push_back(kNoRow);
  s.row_of[hooks[0]] = 0;
  for (std::size_t r = 0; r < s.rows.size(); ++r) {
    for (std::size_t k = 0; k < label; ++k) {
      const rift::Dart x = g.alpha(s.rows[r], hook_dims[k]);
      if (s.row_of[x] == kNoRow) {
        s.row_of[x] = static_cast<std::uint32_t>(s.rows.size());
        s.rows.push_back(x);
        s.parent.push_back(static_cast<std::uint32_t>(r * label + k));
      }
      s.nbr.push_back(s.row_of[x]);
    }
  }
  row_count = s.rows.size();
  for (rift::Dart d : s.rows) s.row_of[d] = kNoRow;
  s.rows.resize(row_count * hook_count);
  for (std::size_t j = 1; j < hook_count; ++j) {
    rift::Dart* rows = s.rows.data() + j * row_count;
    rows[0] = hooks[j];
    for (std::size_t r = 1; r < row_count; ++r) {
      const std::uint32_t p = s.parent[r];
      rows[r] = g.alpha(rows[p / label], hook_dims[p % label]);
    }
    for (std::size_t r = 0; r < row_count; ++r) {
      for (std::size_t k = 0; k < label; ++k) {
        if (g.alpha(rows[r], hook_dims[k]) != rows[s.nbr[r * label + k]]) return false;
      }
    }
  }
  return true;
}

/// The match is injective: no dart plays two nodes or two rows.
[[maybe_unused]] bool distinct_darts(const rift::GMap& g, const rift::Dart* darts, std::size_t count) {
  const rift::Mark m = g.reserve_mark();
  bool ok = true;
  std::size_t k = 0;
  for (; k < count && ok; ++k) {
    if (g.is_marked(darts[k], m)) {
      ok = false;
      break;
    }
    g.mark(darts[k], m);
  }
  for (std::size_t j = 0; j < k; ++j) g.unmark(darts[j], m);
  g.free_mark(m);
  return ok;
}

/// After a rewrite has set its links, gives every embedding orbit touching the rewritten darts
/// one slot: orbits that merged combine their values with the column's policy, an orbit split
/// from another keeps a copy of the value (§4.1), a new orbit gets the defaults.
/// Darts whose slot changes are appended to `touched`.
[[maybe_unused]] void update_embedding_slots(rift::GMap& g, const rift::Dart* darts, std::size_t count, Scratch& s,
                                             std::vector<rift::Dart>* touched) {
  for (const auto& attachment : g.attachments()) {
    rift::OrbitAttachment& att = *attachment;
    const rift::Mark m = g.reserve_mark();
    s.claimed.clear();
    s.marked.clear();
    for (std::size_t k = 0; k < count; ++k) {
      if (g.is_marked(darts[k], m)) continue;
      s.orbit.clear();
      s.slots.clear();
      g.for_each_in_orbit(darts[k], att.orbit(), [&](rift::Dart x) { s.orbit.push_back(x); });
      for (rift::Dart x : s.orbit) {
        g.mark(x, m);
        s.marked.push_back(x);
        const rift::Slot slot = att.slot(x);
        if (slot != rift::kNoSlot && std::find(s.slots.begin(), s.slots.end(), slot) == s.slots.end()) {
          s.slots.push_back(slot);
        }
      }
      auto claimed = [&](rift::Slot slot) {
        return std::find(s.claimed.begin(), s.claimed.end(), slot) != s.claimed.end();
      };
      rift::Slot keep = rift::kNoSlot;
      for (rift::Slot slot : s.slots) {
        if (!claimed(slot)) {
          keep = slot;
          break;
        }
      }
      if (s.slots.empty()) {
        keep = att.allocate_slot();
      } else if (keep == rift::kNoSlot) {
        keep = att.allocate_slot();  // split: this part takes a copy
        for (const auto& column : att.columns()) column->copy_slot(s.slots.front(), keep);
      } else {
        for (rift::Slot other : s.slots) {
          if (other == keep || claimed(other)) continue;
          for (const auto& column : att.columns()) column->merge_into(keep, other);
        }
      }
      s.claimed.push_back(keep);
      for (rift::Dart x : s.orbit) {
        if (att.slot(x) == keep) continue;
        att.assign(x, keep);
        if (touched) touched->push_back(x);
      }
    }
    for (rift::Dart x : s.marked) g.unmark(x, m);
    g.free_mark(m);
  }
}

template <class T>
T zero() {
  if constexpr (std::is_same_v<T, rift::Vec3> || std::is_same_v<T, rift::Mat3>) {
    return T::Zero();
  } else {
    return T{};
  }
}

/// Calls f(value) once per E-orbit inside the orbit <o>(d).
template <class T, class F>
void for_each_value(const rift::GMap& g, const rift::Embedding<T>& e, rift::Dart d, rift::Orbit o, F&& f) {
  Scratch& s = scratch();
  s.seen.clear();
  g.for_each_in_orbit(d, o, [&](rift::Dart x) {
    const rift::Slot slot = e.slot(x);
    if (slot == rift::kNoSlot || std::find(s.seen.begin(), s.seen.end(), slot) != s.seen.end()) return;
    s.seen.push_back(slot);
    f(e[x]);
  });
}

template <class T>
T collect_sum(const rift::GMap& g, const rift::Embedding<T>& e, rift::Dart d, rift::Orbit o) {
  T acc = zero<T>();
  for_each_value(g, e, d, o, [&](const T& v) { acc = acc + v; });
  return acc;
}

template <class T>
std::int64_t collect_count(const rift::GMap& g, const rift::Embedding<T>& e, rift::Dart d, rift::Orbit o) {
  std::int64_t n = 0;
  for_each_value(g, e, d, o, [&](const T&) { ++n; });
  return n;
}

template <class T>
auto collect_mean(const rift::GMap& g, const rift::Embedding<T>& e, rift::Dart d, rift::Orbit o) {
  const T sum = collect_sum(g, e, d, o);
  const auto n = static_cast<rift::Real>(collect_count(g, e, d, o));
  if constexpr (std::is_same_v<T, std::int64_t>) {
    return n > 0 ? static_cast<rift::Real>(sum) / n : rift::Real(0);
  } else {
    return n > 0 ? T(sum / n) : zero<T>();
  }
}

template <class T>
T collect_min(const rift::GMap& g, const rift::Embedding<T>& e, rift::Dart d, rift::Orbit o) {
  T best = std::numeric_limits<T>::max();
  for_each_value(g, e, d, o, [&](const T& v) { best = std::min(best, v); });
  return best;
}

template <class T>
T collect_max(const rift::GMap& g, const rift::Embedding<T>& e, rift::Dart d, rift::Orbit o) {
  T best = std::numeric_limits<T>::lowest();
  for_each_value(g, e, d, o, [&](const T& v) { best = std::max(best, v); });
  return best;
}

// rotation(F) is rift::polar_rotation (runtime/rift/core/polar.hpp), found from this
// namespace by ordinary lookup.

[[maybe_unused]] rift::Vec3 symmetric_eigenvalues(const rift::Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<rift::Mat3>(m, Eigen::EigenvaluesOnly).eigenvalues();
}

[[maybe_unused]] rift::Real symmetric_max_eigenvalue(const rift::Mat3& m) { return symmetric_eigenvalues(m)(2); }

[[maybe_unused]] rift::Vec3 symmetric_max_eigenvector(const rift::Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<rift::Mat3>(m).eigenvectors().col(2);
}

/// A parameter value given by a scene or a caller, as T (an int is accepted for a real).
template <class T>
T value_as(const rift::Value& v, const std::string& what) {
  if constexpr (std::is_same_v<T, rift::Real>) {
    if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<rift::Real>(*i);
  }
  if constexpr (std::is_same_v<T, bool>) {
    if (const auto* b = std::get_if<rift::Bool>(&v)) return b->value;
  } else {
    if (const auto* x = std::get_if<T>(&v)) return *x;
  }
  throw std::invalid_argument(what + " has a value of the wrong type");
}

/// The dart of <o>(d) tagged at initialisation (§3.2: the first dart fixes the
/// order of an element's vertices), or kNoDart.
[[maybe_unused]] rift::Dart tagged_dart(const rift::GMap& g, const rift::Embedding<rift::Bool>& tag, rift::Dart d,
                                        rift::Orbit o) {
  if (tag[d]) return d;
  rift::Dart found = rift::kNoDart;
  g.for_each_in_orbit(d, o, [&](rift::Dart x) {
    if (found == rift::kNoDart && tag[x]) found = x;
  });
  return found;
}

template <class T>
rift::Embedding<T> require_embedding(const rift::GMap& g, const char* name, const char* user) {
  rift::Embedding<T> e = g.embedding<T>(name);
  if (!e) {
    throw std::invalid_argument(std::string(user) + " reads embedding '" + name +
                                "', which the map does not have (call declare_embeddings first)");
  }
  return e;
}

}  // namespace
)RIFT";
}

}  // namespace rift::emit
