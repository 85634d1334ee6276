#include "rift/generated/match_rows.hpp"

#include <cstdint>
#include <vector>

namespace rift::generated {

namespace {

// The rows found so far by dart: an open-addressing table of (dart << 32 |
// row) sized to the orbit being walked (a few darts to a few hundred), so
// that matching costs the orbit's size. A per-dart array of rows, as before,
// was filled over the whole map at the first rule applied to it (32 MB and
// 0.1 s on a 10^6-vertex cloth's first tear) and at every growth of the map.
class RowIndex {
 public:
  explicit RowIndex(std::vector<std::uint64_t>& table) : table_(table) { reset(kInitialBits); }

  std::uint32_t find(Dart d) const {
    for (std::size_t i = home(d);; i = (i + 1) & mask_) {
      if (table_[i] == kEmpty) return kNoRow;
      if (static_cast<Dart>(table_[i] >> 32) == d) return static_cast<std::uint32_t>(table_[i]);
    }
  }
  /// d (not yet in the table) is row r; `rows` lists every row's dart so far.
  void insert(Dart d, std::uint32_t r, const std::vector<Dart>& rows) {
    if (2 * (static_cast<std::size_t>(r) + 1) > table_.size()) {
      reset(bits_ + 1);
      for (std::uint32_t k = 0; k < r; ++k)
        place(rows[k], k);
    }
    place(d, r);
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static constexpr int kInitialBits = 6;

  void reset(int bits) {
    bits_ = bits;
    mask_ = (std::size_t{1} << bits) - 1;
    table_.assign(std::size_t{1} << bits, kEmpty);
  }
  // Fibonacci hashing: darts of one orbit are often consecutive numbers.
  std::size_t home(Dart d) const {
    return static_cast<std::size_t>((std::uint64_t{d} * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
  }
  void place(Dart d, std::uint32_t r) {
    std::size_t i = home(d);
    while (table_[i] != kEmpty)
      i = (i + 1) & mask_;
    table_[i] = (std::uint64_t{d} << 32) | r;
  }

  std::vector<std::uint64_t>& table_;
  int bits_ = 0;
  std::size_t mask_ = 0;
};

}  // namespace

bool build_rows(const GMap& g, const Dart* hooks, std::size_t hook_count, const int* hook_dims,
                std::size_t label, Scratch& s, std::size_t& row_count) {
  s.rows.clear();
  s.nbr.clear();
  s.parent.clear();
  if (hook_count == 0) {
    row_count = 1;
    return true;
  }
  // Breadth-first from the first hook; parent[r] records the link that reached
  // row r, so the other hooks replay the same walk without searching.
  RowIndex row_of(s.row_index);
  s.rows.push_back(hooks[0]);
  s.parent.push_back(kNoRow);
  row_of.insert(hooks[0], 0, s.rows);
  for (std::size_t r = 0; r < s.rows.size(); ++r) {
    for (std::size_t k = 0; k < label; ++k) {
      const Dart x = g.alpha(s.rows[r], hook_dims[k]);
      std::uint32_t row = row_of.find(x);
      if (row == kNoRow) {
        row = static_cast<std::uint32_t>(s.rows.size());
        row_of.insert(x, row, s.rows);
        s.rows.push_back(x);
        s.parent.push_back(static_cast<std::uint32_t>(r * label + k));
      }
      s.nbr.push_back(row);
    }
  }
  row_count = s.rows.size();
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
