#include "lower/orbit_memo.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>

namespace rift::lower {

namespace {

using ir::ExprId;
using ir::Node;
using ir::Op;

/// A fold enclosing the node being looked at.
struct Enclosing {
  int var = -1;
  std::vector<int> sub;  // the sub-orbit its variable's dart stands for
  int depth = 0;         // 1 = outermost
};

class MemoPlanner {
 public:
  MemoPlanner(const ir::Body& body, const std::vector<int>& cell_orbit,
              const EmbeddingOrbit& embedding_orbit)
      : body_(body), g_(body.graph), cell_orbit_(cell_orbit), embedding_orbit_(embedding_orbit) {}

  /// Pass 1: whether each aggregate or fold may be memoised everywhere it is met.
  void judge(ExprId id) {
    if (id == ir::kNoExpr || !seen_.insert({id, context_key()}).second) return;
    const Node& n = g_[id];
    if (n.op == Op::Fold) {
      const bool ok = memoisable(id);
      auto [it, fresh] = ok_.emplace(id, ok);
      if (!fresh) it->second = it->second && ok;
    }
    for_operands(id, [this](ExprId k) { judge(k); });
  }

  /// Pass 2: the outermost nodes judged memoisable.
  void choose(ExprId id) {
    if (id == ir::kNoExpr || !chosen_seen_.insert({id, context_key()}).second) return;
    if (const auto it = ok_.find(id); it != ok_.end() && it->second) {
      chosen_.insert(id);
      return;
    }
    for_operands(id, [this](ExprId k) { choose(k); });
  }

  std::vector<ir::OrbitMemo> memos() const {
    std::vector<ir::OrbitMemo> out;
    std::map<std::pair<int, std::vector<int>>, std::size_t> index;
    for (const ExprId id : chosen_) {  // in node order
      const Node& n = g_[id];
      std::vector<int> orbit = orbit_of(n);
      std::sort(orbit.begin(), orbit.end());
      const auto key = std::make_pair(n.place.node, orbit);
      auto it = index.find(key);
      if (it == index.end() || out[it->second].values.size() == 64) {
        ir::OrbitMemo memo;
        memo.var = n.place.node;
        memo.orbit = orbit;
        out.push_back(std::move(memo));
        it = index.insert_or_assign(key, out.size() - 1).first;
      }
      out[it->second].values.push_back(id);
    }
    return out;
  }

 private:
  /// Calls f on each operand of `id`, the body of a fold inside its scope.
  template <class F>
  void for_operands(ExprId id, F&& f) {
    const Node& n = g_[id];
    if (n.op == Op::Fold) {
      enclosing_.push_back({n.var, n.orbit, static_cast<int>(enclosing_.size()) + 1});
      f(n.a);
      enclosing_.pop_back();
      return;
    }
    for (std::size_t k = 0; k < n.arity(); ++k)
      f(n.operand(k));
  }

  std::string context_key() const {
    std::string key;
    for (const Enclosing& e : enclosing_) {
      key += std::to_string(e.var) + ":";
      for (int d : e.sub)
        key += std::to_string(d);
      key += ';';
    }
    return key;
  }

  std::vector<int> orbit_of(const Node& n) const {
    if (n.op == Op::Fold) return n.outer;
    return embedding_orbit_(n.embedding);  // Read
  }

  bool memoisable(ExprId id) const {
    const Node& n = g_[id];
    const auto e = std::find_if(enclosing_.rbegin(), enclosing_.rend(),
                                [&](const Enclosing& x) { return x.var == n.place.node; });
    if (e == enclosing_.rend() || !n.place.hops.empty()) return false;
    const auto i = static_cast<std::size_t>(id);
    if (!body_.sharing.speculable[i] ||
        body_.sharing.fold_vars[i] != (std::uint32_t{1} << e->depth))
      return false;
    const std::vector<int> orbit = orbit_of(n);
    if (!orbit_contains(orbit, e->sub) || orbit_contains(cell_orbit_, orbit)) return false;
    std::map<int, std::vector<int>> bound = {{n.var, n.orbit}};
    return reads_only_its_orbit(n.a, bound);
  }

  /// Whether `id` reads the map only at the variables of `bound` (folds
  /// inside the memoised node), each on orbits that contain its sub-orbit.
  bool reads_only_its_orbit(ExprId id, std::map<int, std::vector<int>>& bound) const {
    const Node& n = g_[id];
    switch (n.op) {
      case Op::Let:
      case Op::Position:
      case Op::Velocity:
      case Op::PositionTangent:
      case Op::VelocityTangent:
        return false;
      case Op::Read:
      case Op::Fold: {
        const auto it = bound.find(n.place.node);
        if (it == bound.end() || !n.place.hops.empty() || !orbit_contains(orbit_of(n), it->second))
          return false;
        break;
      }
      default:
        break;
    }
    if (n.op == Op::Fold) {
      auto [it, fresh] = bound.try_emplace(n.var, n.orbit);
      std::vector<int> before = fresh ? std::vector<int>{} : std::exchange(it->second, n.orbit);
      const bool ok = reads_only_its_orbit(n.a, bound);
      if (fresh) {
        bound.erase(n.var);
      } else {
        bound[n.var] = std::move(before);
      }
      return ok;
    }
    for (std::size_t k = 0; k < n.arity(); ++k) {
      if (!reads_only_its_orbit(n.operand(k), bound)) return false;
    }
    return true;
  }

  const ir::Body& body_;
  const ir::Graph& g_;
  const std::vector<int>& cell_orbit_;
  const EmbeddingOrbit& embedding_orbit_;
  std::vector<Enclosing> enclosing_;
  std::set<std::pair<ExprId, std::string>> seen_, chosen_seen_;
  std::map<ExprId, bool> ok_;
  std::set<ExprId> chosen_;
};

}  // namespace

bool orbit_contains(const std::vector<int>& outer, const std::vector<int>& inner) {
  return std::all_of(inner.begin(), inner.end(), [&](int d) {
    return std::find(outer.begin(), outer.end(), d) != outer.end();
  });
}

std::vector<ir::OrbitMemo> plan_orbit_memos(const ir::Body& body,
                                            const std::vector<ir::ExprId>& roots,
                                            const std::vector<int>& cell_orbit,
                                            const EmbeddingOrbit& embedding_orbit) {
  MemoPlanner planner(body, cell_orbit, embedding_orbit);
  for (const ExprId r : roots)
    planner.judge(r);
  for (const ExprId r : roots)
    planner.choose(r);
  return planner.memos();
}

}  // namespace rift::lower
