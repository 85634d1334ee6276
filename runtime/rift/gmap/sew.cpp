// G-map sewing and unsewing along dimension i, with embedding merge and split.
#include <algorithm>
#include <string>

#include "rift/gmap/gmap.hpp"

namespace rift {

namespace {
std::string dart_str(Dart d) {
  return "dart " + std::to_string(d);
}
}  // namespace

std::string GMap::pair_sewing_orbits(Dart a, Dart b, int i, std::vector<Dart>& pairs) const {
  pairs.clear();
  if (i < 0 || i > dimension_) {
    return "dimension " + std::to_string(i) + " is outside [0, " + std::to_string(dimension_) + "]";
  }
  if (!is_alive(a) || !is_alive(b)) return "sewing a dead dart";
  if (a == b) return "cannot sew " + dart_str(a) + " to itself";
  if (partner_.size() < alive_.size()) partner_.resize(alive_.size(), kNoDart);

  const Orbit sewing = Orbit::sewing(i, dimension_);
  std::string why;
  partner_[a] = b;
  partner_[b] = a;
  pairs.push_back(a);
  pairs.push_back(b);
  for (std::size_t k = 0; k < pairs.size() && why.empty(); k += 2) {
    const Dart x = pairs[k];
    const Dart y = pairs[k + 1];
    if (!is_free(x, i) || !is_free(y, i)) {
      why = dart_str(is_free(x, i) ? y : x) + " is already " + std::to_string(i) + "-sewn";
      break;
    }
    for (int j = 0; j <= dimension_; ++j) {
      if (!sewing.contains(j)) continue;
      const Dart xj = alpha_[j][x];
      const Dart yj = alpha_[j][y];
      if ((xj == x) != (yj == y)) {
        why = "orbits are not isomorphic: " + dart_str(xj == x ? x : y) + " is " +
              std::to_string(j) + "-free but its counterpart is not";
        break;
      }
      if (partner_[xj] == kNoDart && partner_[yj] == kNoDart) {
        partner_[xj] = yj;
        partner_[yj] = xj;
        pairs.push_back(xj);
        pairs.push_back(yj);
      } else if (partner_[xj] != yj || partner_[yj] != xj) {
        why = "orbits are not isomorphic around " + dart_str(xj);
        break;
      }
    }
  }
  for (Dart d : pairs)
    partner_[d] = kNoDart;
  if (!why.empty()) {
    pairs.clear();
    return why;
  }

  // Refusing embeddings veto the merge of two different values.
  for (const auto& att : attachments_) {
    // A dormant attachment's columns hold only defaults, which merge.
    if (!att->orbit().contains(i) || att->dormant()) continue;
    for (const auto& column : att->columns()) {
      if (column->policy() != MergePolicy::kRefuse) continue;
      for (std::size_t k = 0; k < pairs.size(); k += 2) {
        const Slot sx = att->slot(pairs[k]);
        const Slot sy = att->slot(pairs[k + 1]);
        if (sx != kNoSlot && sy != kNoSlot && sx != sy && !column->equal(sx, sy)) {
          pairs.clear();
          return "embedding '" + column->name() + "' refuses to merge two different values";
        }
      }
    }
  }
  return {};
}

std::string GMap::why_not_sewable(Dart a, Dart b, int i) const {
  std::vector<Dart>& pairs = acquire_scratch();
  std::string why = pair_sewing_orbits(a, b, i, pairs);
  release_scratch();
  return why;
}

bool GMap::sew(Dart a, Dart b, int i) {
  std::vector<Dart>& pairs = acquire_scratch();
  if (!pair_sewing_orbits(a, b, i, pairs).empty()) {
    release_scratch();
    return false;
  }
  for (std::size_t k = 0; k < pairs.size(); k += 2) {
    // A pair may appear once as (x, y); its mirror is never pushed.
    if (is_free(pairs[k], i) && is_free(pairs[k + 1], i)) link(pairs[k], pairs[k + 1], i);
  }
  merge_embeddings_after_sew(pairs, i);
  release_scratch();
  check_after_rewrite("sew");
  return true;
}

void GMap::merge_embeddings_after_sew(const std::vector<Dart>& pairs, int i) {
  for (auto& att : attachments_) {
    const Orbit o = att->orbit();
    if (!o.contains(i) || att->dormant()) continue;
    for (std::size_t k = 0; k < pairs.size(); k += 2) {
      const Dart x = pairs[k];
      const Slot sx = att->slot(x);
      const Slot sy = att->slot(pairs[k + 1]);
      if (sx == sy) continue;
      if (sx != kNoSlot && sy != kNoSlot) {
        for (const auto& column : att->columns())
          column->merge_into(sx, sy);
        for_each_in_orbit(x, o, [&](Dart z) {
          if (att->slot(z) == sy) att->assign(z, sx);
        });
      } else {
        const Slot keep = sx != kNoSlot ? sx : sy;
        for_each_in_orbit(x, o, [&](Dart z) {
          if (att->slot(z) == kNoSlot) att->assign(z, keep);
        });
      }
    }
  }
}

void GMap::unsew(Dart a, int i) {
  assert(is_alive(a) && i >= 0 && i <= dimension_);
  std::vector<Dart>& pairs = acquire_scratch();
  pairs.clear();
  for_each_in_orbit(a, Orbit::sewing(i, dimension_), [&](Dart x) {
    const Dart y = alpha_[i][x];
    if (y != x) {
      pairs.push_back(x);
      pairs.push_back(y);
    }
  });
  for (std::size_t k = 0; k < pairs.size(); k += 2)
    unlink(pairs[k], i);
  split_embeddings_after_unsew(pairs, i);
  release_scratch();
  check_after_rewrite("unsew");
}

void GMap::split_embeddings_after_unsew(const std::vector<Dart>& pairs, int i) {
  // Removing the i-links may cut an embedding orbit into several parts; every
  // part contains an end of a removed link. The first part met keeps the
  // slot, each further part of the same old orbit gets a copy of its values.
  for (auto& att : attachments_) {
    const Orbit o = att->orbit();
    if (!o.contains(i) || att->dormant()) continue;
    const Mark m = reserve_mark();
    std::vector<Dart>& claimed = acquire_scratch();  // slots already kept by a part
    claimed.clear();
    std::vector<Dart>& part = acquire_scratch();
    for (Dart seed : pairs) {
      const Slot s = att->slot(seed);
      if (is_marked(seed, m) || s == kNoSlot) continue;
      part.clear();
      for_each_in_orbit(seed, o, [&](Dart z) {
        mark(z, m);
        part.push_back(z);
      });
      if (std::find(claimed.begin(), claimed.end(), s) == claimed.end()) {
        claimed.push_back(s);
        continue;
      }
      const Slot copy = att->allocate_slot();
      for (const auto& column : att->columns())
        column->copy_slot(s, copy);
      for (Dart z : part)
        att->assign(z, copy);
    }
    release_scratch();
    release_scratch();
    for (Dart seed : pairs) {
      if (is_marked(seed, m)) {
        for_each_in_orbit(seed, o, [&](Dart z) { unmark(z, m); });
      }
    }
    free_mark(m);
  }
}

}  // namespace rift
