// The parallel passes give the same bits whatever the thread count
// (rift/core/parallel.hpp, rift/sim/term_gather.hpp).
#include "rift/core/parallel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "rift/sim/term_gather.hpp"
#include "same_bits.hpp"
#include "thread_count_guard.hpp"

namespace rift {
namespace {

using test::same_bits;
using test::ThreadCountGuard;

// Values of very different magnitudes: any change of the order of the
// additions changes the rounded sum.
std::vector<Real> mixed_values(std::size_t n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<Real> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-30, 30);
  std::vector<Real> v(n);
  for (Real& x : v)
    x = std::ldexp(mantissa(rng), exponent(rng));
  return v;
}

TEST(Parallel, SumIsTheBlockOrderSumForAnyThreadCount) {
  ThreadCountGuard guard;
  const std::size_t n = 50 * kParallelBlock + 17;
  const std::vector<Real> v = mixed_values(n);
  // The definition: each block summed in order, the partial sums in block order.
  Real expected = 0;
  for (std::size_t first = 0; first < n; first += kParallelBlock) {
    Real block = 0;
    for (std::size_t i = first; i < std::min(n, first + kParallelBlock); ++i)
      block += v[i];
    expected += block;
  }
  Real plain = 0;
  for (Real x : v)
    plain += x;
  ASSERT_FALSE(same_bits(plain, expected)) << "the values do not tell the orders apart";
  for (int threads : {1, 2, 3, 8}) {
    set_thread_count(threads);
    const Real s = parallel_sum(n, [&](std::size_t i) { return v[i]; });
    EXPECT_TRUE(same_bits(s, expected)) << threads << " threads: " << s << " vs " << expected;
  }
}

TEST(Parallel, ForVisitsEveryItemOnce) {
  ThreadCountGuard guard;
  for (int threads : {1, 2, 8}) {
    set_thread_count(threads);
    std::vector<int> visits(10 * kParallelBlock + 3, 0);
    parallel_for(visits.size(), [&](std::size_t i) { ++visits[i]; });
    for (std::size_t i = 0; i < visits.size(); ++i)
      ASSERT_EQ(visits[i], 1) << "item " << i << ", " << threads << " threads";
  }
}

TEST(Parallel, AnExceptionInABlockReachesTheCallerAfterThePass) {
  ThreadCountGuard guard;
  for (int threads : {1, 4}) {
    set_thread_count(threads);
    std::vector<int> done(64, 0);
    auto body = [&](std::size_t first, std::size_t) {
      if (first / 10 == 3 || first / 10 == 5) {
        throw std::runtime_error("block " + std::to_string(first / 10));
      }
      done[first / 10] = 1;
    };
    try {
      parallel_blocks(640, 10, body);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      // The lowest failing block, whatever the threads.
      EXPECT_STREQ(e.what(), "block 3") << threads << " threads";
    }
    EXPECT_EQ(done[0], 1);
    // Several threads finish the pass (the blocks run at once); one thread
    // stops at the first exception.
    if (thread_count() > 1) {
      EXPECT_EQ(done[63], 1);
    }
  }
}

TEST(Parallel, TheThreadCountIsWhatWasAsked) {
  ThreadCountGuard guard;
  set_thread_count(3);
  EXPECT_EQ(thread_count(), 3);
  set_thread_count(0);
  EXPECT_GE(thread_count(), 1);
}

// A gather adds each slot's terms in increasing term order: the bits of the
// sequential scatter `out[target[t]] += term[t]`, on any number of threads.
TEST(TermGather, EqualsTheSequentialScatterBitForBit) {
  ThreadCountGuard guard;
  std::mt19937 rng(3);
  const std::size_t slots = 5000, terms = 40000;
  std::uniform_int_distribution<Slot> pick(0, slots - 1);
  std::vector<Slot> targets(terms);
  for (std::size_t t = 0; t < terms; ++t)
    targets[t] = t % 97 == 0 ? kNoSlot : pick(rng);
  const std::vector<Real> values = mixed_values(3 * terms);
  std::vector<Vec3> term(terms);
  for (std::size_t t = 0; t < terms; ++t)
    term[t] = Vec3(values[3 * t], values[3 * t + 1], values[3 * t + 2]);
  std::vector<Vec3> start(slots);
  for (std::size_t s = 0; s < slots; ++s)
    start[s] = Vec3(Real(s), -Real(s), 0.5);

  std::vector<Vec3> expected = start;
  for (std::size_t t = 0; t < terms; ++t)
    if (targets[t] != kNoSlot) expected[targets[t]] += term[t];

  TermGather gather;
  gather.build(targets);
  EXPECT_LE(gather.slots(), slots);
  for (int threads : {1, 2, 8}) {
    set_thread_count(threads);
    std::vector<Vec3> out = start;
    gather.add_to(term.data(), out.data());
    ASSERT_EQ(std::memcmp(out.data(), expected.data(), slots * sizeof(Vec3)), 0)
        << threads << " threads";
  }
  // Built again (the same arrays reused) after the targets changed.
  for (std::size_t t = 0; t < terms; t += 3)
    targets[t] = pick(rng);
  gather.build(targets);
  expected = start;
  for (std::size_t t = 0; t < terms; ++t)
    if (targets[t] != kNoSlot) expected[targets[t]] += term[t];
  set_thread_count(2);
  std::vector<Vec3> out = start;
  gather.add_to(term.data(), out.data());
  EXPECT_EQ(std::memcmp(out.data(), expected.data(), slots * sizeof(Vec3)), 0);
}

}  // namespace
}  // namespace rift
