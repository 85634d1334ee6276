// keys_all_distinct (rift/sim/distinct_keys.hpp): whether an interaction's
// matches all have keys of their own, told without building the groups.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "rift/sim/distinct_keys.hpp"

namespace {

// A match whose key is its own words: a first word (a vertex slot) and the rest.
struct KeyedMatch {
  std::uint64_t words[4];
};

auto key_of(int words) {
  return [words](const KeyedMatch& m, std::uint64_t* out) {
    for (int i = 0; i < words; ++i)
      out[i] = m.words[i];
  };
}

// n matches with distinct keys: first words among `vertices`, every key
// (first word, second word) different.
std::vector<KeyedMatch> distinct_matches(std::size_t n, std::uint32_t vertices, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<KeyedMatch> ms(n);
  for (std::size_t i = 0; i < n; ++i) {
    ms[i].words[0] = rng() % vertices;
    ms[i].words[1] = i;  // makes the key unique
    ms[i].words[2] = rng();
    ms[i].words[3] = 0x3FF0000000000000ull;  // the bits of 1.0, as a stiffness would be
  }
  return ms;
}

bool distinct(const std::vector<KeyedMatch>& ms, int words, std::size_t first_words) {
  return rift::keys_all_distinct<KeyedMatch>(std::span<const KeyedMatch>(ms), words, key_of(words),
                                             first_words);
}

TEST(DistinctKeys, DistinctKeysAreToldDistinctWithAndWithoutTheFirstWordsBound) {
  for (std::size_t n :
       {std::size_t{0}, std::size_t{1}, std::size_t{1000}, rift::kDistinctKeysPrefix + 5000}) {
    const auto ms = distinct_matches(n, 997, 7);
    EXPECT_TRUE(distinct(ms, 4, 997)) << n;
    EXPECT_TRUE(distinct(ms, 4, 0)) << n;  // bound unknown: sorted instead of bucketed
  }
}

TEST(DistinctKeys, ASharedKeyIsFoundWhereverItsTwoMatchesAre) {
  const std::size_t n = 3 * rift::kDistinctKeysPrefix;
  // Within the prefix, across it, and both far beyond it.
  const std::size_t pairs[][2] = {{3, 9}, {10, n - 1}, {n - 2, n - 1}, {n / 2, n / 2 + 4000}};
  for (const auto& p : pairs) {
    auto ms = distinct_matches(n, 5000, 11);
    ms[p[1]] = ms[p[0]];
    EXPECT_FALSE(distinct(ms, 4, 5000)) << p[0] << " " << p[1];
    EXPECT_FALSE(distinct(ms, 4, 0)) << p[0] << " " << p[1];
  }
}

TEST(DistinctKeys, KeysDifferingInTheirLastWordOnlyAreDistinct) {
  auto ms = distinct_matches(2 * rift::kDistinctKeysPrefix, 100, 3);
  // Two matches agree on every word but the last (a rest length's last bit).
  ms[ms.size() - 1] = ms[20];
  ms[ms.size() - 1].words[3] ^= 1;
  EXPECT_TRUE(distinct(ms, 4, 100));
  // Read as three words the two keys are equal.
  EXPECT_FALSE(distinct(ms, 3, 100));
}

TEST(DistinctKeys, AFirstWordBeyondTheBoundFallsBackToSorting) {
  auto ms = distinct_matches(2 * rift::kDistinctKeysPrefix, 100, 5);
  ms.back().words[0] = 1u << 20;  // not a slot below the bound
  EXPECT_TRUE(distinct(ms, 4, 100));
  ms[ms.size() - 2] = ms.back();
  EXPECT_FALSE(distinct(ms, 4, 100));
}

TEST(DistinctKeys, KeysTooLongToCompareAreNeverCalledDistinct) {
  const auto ms = distinct_matches(10, 10, 1);
  EXPECT_FALSE(distinct(ms, 0, 10));
  EXPECT_FALSE(rift::keys_all_distinct<KeyedMatch>(
      std::span<const KeyedMatch>(ms), 65, [](const KeyedMatch&, std::uint64_t*) {}, 10));
}

}  // namespace
