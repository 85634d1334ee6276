#include "lower/distinct_pairs.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace rift::lower {

namespace {

// Union-find over the pairs {a, b}, a < b, indexed a * nodes + b.
class PairClasses {
 public:
  explicit PairClasses(int nodes)
      : nodes_(nodes), parent_(static_cast<std::size_t>(nodes) * static_cast<std::size_t>(nodes)) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t index(int a, int b) const {
    if (a > b) std::swap(a, b);
    return static_cast<std::size_t>(a) * static_cast<std::size_t>(nodes_) +
           static_cast<std::size_t>(b);
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  // The smaller index stays the root: a class's root is its first pair.
  void join(std::size_t x, std::size_t y) {
    x = find(x);
    y = find(y);
    if (x == y) return;
    if (y < x) std::swap(x, y);
    parent_[y] = x;
  }

 private:
  int nodes_;
  std::vector<std::size_t> parent_;
};

}  // namespace

std::vector<std::pair<int, int>> distinct_pairs(int nodes, const MatchPlan& plan) {
  // Each node's partner along each dimension it has an arc of (itself for a
  // loop), -1 without one.
  int dims = 0;
  for (const Follow& f : plan.follows)
    dims = std::max(dims, f.dim + 1);
  for (const ArcCheck& a : plan.arc_checks)
    dims = std::max(dims, a.dim + 1);
  const auto n = static_cast<std::size_t>(nodes);
  std::vector<std::vector<int>> partner(static_cast<std::size_t>(dims), std::vector<int>(n, -1));
  std::vector<bool> ambiguous(static_cast<std::size_t>(dims), false);
  auto link = [&](int a, int b, int dim) {
    auto& p = partner[static_cast<std::size_t>(dim)];
    for (auto [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
      int& slot = p[static_cast<std::size_t>(x)];
      // Two arcs of one dimension at a node (a pattern the checks reject):
      // that dimension proves nothing.
      if (slot != -1 && slot != y) ambiguous[static_cast<std::size_t>(dim)] = true;
      slot = y;
    }
  };
  for (const Follow& f : plan.follows)
    link(f.from, f.to, f.dim);
  for (const ArcCheck& a : plan.arc_checks)
    link(a.a, a.b, a.dim);

  PairClasses classes(nodes);
  for (std::size_t d = 0; d < partner.size(); ++d) {
    if (ambiguous[d]) continue;
    const std::vector<int>& p = partner[d];
    for (int a = 0; a < nodes; ++a) {
      for (int b = a + 1; b < nodes; ++b) {
        const int pa = p[static_cast<std::size_t>(a)], pb = p[static_cast<std::size_t>(b)];
        // pa == pb cannot happen for a != b with one arc per dimension.
        if (pa < 0 || pb < 0 || pa == pb) continue;
        classes.join(classes.index(a, b), classes.index(pa, pb));
      }
    }
  }
  std::vector<std::pair<int, int>> out;
  for (int a = 0; a < nodes; ++a) {
    for (int b = a + 1; b < nodes; ++b) {
      const std::size_t x = classes.index(a, b);
      if (classes.find(x) == x) out.emplace_back(a, b);
    }
  }
  return out;
}

}  // namespace rift::lower
