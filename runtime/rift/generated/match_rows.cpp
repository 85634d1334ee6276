#include "rift/generated/match_rows.hpp"

namespace rift::generated {

bool build_rows(const GMap& g, const Dart* hooks, std::size_t hook_count, const int* hook_dims,
                std::size_t label, Scratch& s, std::size_t& row_count) {
  if (s.row_of.size() < g.capacity()) s.row_of.resize(g.capacity(), kNoRow);
  s.rows.clear();
  s.nbr.clear();
  s.parent.clear();
  if (hook_count == 0) {
    row_count = 1;
    return true;
  }
  // Breadth-first from the first hook; parent[r] records the link that reached
  // row r, so the other hooks replay the same walk without searching.
  s.rows.push_back(hooks[0]);
  s.parent.push_back(kNoRow);
  s.row_of[hooks[0]] = 0;
  for (std::size_t r = 0; r < s.rows.size(); ++r) {
    for (std::size_t k = 0; k < label; ++k) {
      const Dart x = g.alpha(s.rows[r], hook_dims[k]);
      if (s.row_of[x] == kNoRow) {
        s.row_of[x] = static_cast<std::uint32_t>(s.rows.size());
        s.rows.push_back(x);
        s.parent.push_back(static_cast<std::uint32_t>(r * label + k));
      }
      s.nbr.push_back(s.row_of[x]);
    }
  }
  row_count = s.rows.size();
  for (Dart d : s.rows)
    s.row_of[d] = kNoRow;
  s.rows.resize(row_count * hook_count);
  for (std::size_t j = 1; j < hook_count; ++j) {
    // Hook j walks with its own label: the link at position k is dims[k],
    // which may differ from the first hook's (Jerboa's renaming).
    const int* const dims = hook_dims + j * label;
    Dart* rows = s.rows.data() + j * row_count;
    rows[0] = hooks[j];
    for (std::size_t r = 1; r < row_count; ++r) {
      const std::uint32_t p = s.parent[r];
      rows[r] = g.alpha(rows[p / label], dims[p % label]);
    }
    // The replayed walk must close the same way: every link lands on the row
    // the first hook's walk found there.
    for (std::size_t r = 0; r < row_count; ++r) {
      for (std::size_t k = 0; k < label; ++k) {
        if (g.alpha(rows[r], dims[k]) != rows[s.nbr[r * label + k]]) return false;
      }
    }
  }
  return true;
}

bool distinct_darts(const GMap& g, const Dart* darts, std::size_t count) {
  const Mark m = g.reserve_mark();
  bool ok = true;
  std::size_t k = 0;
  for (; k < count && ok; ++k) {
    if (g.is_marked(darts[k], m)) {
      ok = false;
      break;
    }
    g.mark(darts[k], m);
  }
  for (std::size_t j = 0; j < k; ++j)
    g.unmark(darts[j], m);
  g.free_mark(m);
  return ok;
}

}  // namespace rift::generated
