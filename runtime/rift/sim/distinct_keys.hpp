// Whether every match of an interaction has a group key of its own, answered
// without building the groups (issue 12, set-up of large meshes).
//
// CachedInteraction groups an interaction's matches (match_groups.hpp) and
// keeps the groups only where some matches share a key. Finite elements, a
// hexahedral block's body diagonals and its faces' shear springs (tagged:
// each volume lists its face from its own dart) share none, and building
// their groups only to drop them (keys, table and member links for 6.8
// million matches, hundreds of MB touched once and given back) cost a
// 10^6-vertex hexahedral block's set-up 1 to 2 of its 12 s.
//
// This pass computes each key once and keeps its first word (a vertex slot,
// for generated kernels) and a 64-bit hash of the whole key: 12 bytes a
// match instead of the groups' 80 or more. It buckets the hashes by first
// word (a counting sort) and looks for two equal hashes in one bucket. Equal
// keys have equal first words and equal hashes, so "all distinct" is never
// wrong; two distinct keys whose hashes collide only send the caller to the
// full build, which then finds the keys distinct and decides as before. The
// answer decides nothing but whether the build runs: the groups, when they
// are built, are the same.
//
// An interaction whose matches do share keys (atomic springs: an interior
// edge's two faces) shows it within its first matches, which neighbour in
// dart order: a prefix is checked first, and the whole pass runs only when
// the prefix has no shared key.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "rift/core/huge_pages.hpp"

namespace rift {

namespace detail {

/// A 64-bit hash of a key's words (a multiply-rotate mix per word and a
/// final avalanche). Quality only affects how often a collision sends the
/// caller to the full build.
inline std::uint64_t hash_key_words(const std::uint64_t* words, int n) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(n);
  for (int i = 0; i < n; ++i) {
    h ^= words[i] + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  }
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  return h;
}

/// Whether the (first word, hash) pairs are pairwise distinct, by sorting.
inline bool pairs_distinct(std::vector<std::pair<std::uint64_t, std::uint64_t>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  return std::adjacent_find(pairs.begin(), pairs.end()) == pairs.end();
}

}  // namespace detail

/// Matches whose keys the prefix check reads before the whole pass.
inline constexpr std::size_t kDistinctKeysPrefix = std::size_t{1} << 14;

/// True when no two of `matches` can have equal keys: key(const Match&,
/// std::uint64_t* out) writes `words` (1 to kMaxWords) words. first_words: the
/// number of values a key's first word takes (the vertex slots), or 0 when
/// unknown (the pass then sorts instead of bucketing). False means that two
/// keys may be equal, not that they are.
template <class Match, class KeyFn>
bool keys_all_distinct(std::span<const Match> matches, int words, KeyFn&& key,
                       std::size_t first_words) {
  constexpr int kMaxWords = 64;
  if (words < 1 || words > kMaxWords) return false;
  const std::size_t n = matches.size();
  if (n < 2) return true;
  std::uint64_t k[kMaxWords];
  // The prefix: its neighbours in dart order share their keys, if any do.
  {
    const std::size_t m = std::min(n, kDistinctKeysPrefix);
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs(m);
    for (std::size_t i = 0; i < m; ++i) {
      key(matches[i], k);
      pairs[i] = {k[0], detail::hash_key_words(k, words)};
    }
    if (!detail::pairs_distinct(pairs)) return false;
    if (m == n) return true;
  }
  // The whole pass: first words and hashes, then the hashes bucketed by
  // first word, then each bucket (a vertex heads a few dozen keys at most)
  // searched for an equal pair.
  std::vector<std::uint32_t> first;
  std::vector<std::uint64_t> hashes;
  reserve_huge(first, n);
  reserve_huge(hashes, n);
  bool bucketed = first_words != 0 && first_words < (std::size_t{1} << 32);
  for (std::size_t i = 0; i < n; ++i) {
    key(matches[i], k);
    if (k[0] >= first_words) bucketed = false;
    first.push_back(static_cast<std::uint32_t>(k[0]));
    hashes.push_back(detail::hash_key_words(k, words));
  }
  if (!bucketed) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs(n);
    for (std::size_t i = 0; i < n; ++i)
      pairs[i] = {first[i], hashes[i]};
    return detail::pairs_distinct(pairs);
  }
  std::vector<std::uint32_t> start(first_words + 1, 0);
  for (const std::uint32_t f : first)
    ++start[f + 1];
  for (std::size_t s = 0; s < first_words; ++s)
    start[s + 1] += start[s];
  std::vector<std::uint64_t> by_first;
  reserve_huge(by_first, n);
  by_first.resize(n);
  {
    std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      by_first[at[first[i]]++] = hashes[i];
  }
  for (std::size_t s = 0; s < first_words; ++s) {
    const auto b = by_first.begin() + start[s], e = by_first.begin() + start[s + 1];
    if (e - b < 2) continue;
    std::sort(b, e);
    if (std::adjacent_find(b, e) != e) return false;
  }
  return true;
}

}  // namespace rift
