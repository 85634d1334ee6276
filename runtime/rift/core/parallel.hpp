// Every core, with results that do not depend on how many there are.
//
// The passes of a step (forces, integrator sweeps, criteria, the implicit
// solver's products) cut their work into blocks of a fixed size, independent
// of the thread count, and spread the blocks over the threads (a pool of
// sleeping std::threads, parallel.cpp says why not OpenMP). A block writes only its own outputs,
// and anything summed across blocks is combined in block order afterwards, so the same input gives
// the same bits with 1, 2 or 64 threads (floating-point addition is not associative: a reduction
// whose order followed the threads would not).
//
// Headers and generated code call parallel_blocks with a callable: one
// indirect call per block, no thread code of their own.
#pragma once

#include <cstddef>
#include <span>
#include <type_traits>

#include "rift/core/types.hpp"

// Inlines every call of the function it marks (the blocks' loops below).
#if defined(__GNUC__)
#define RIFT_FLATTEN __attribute__((flatten))
#else
#define RIFT_FLATTEN
#endif

namespace rift {

/// Items per block of the passes that do not choose their own: large enough
/// that handing a block to a thread costs nothing next to its work, small
/// enough that a 10⁴-vertex mesh still spreads over a few threads.
inline constexpr std::size_t kParallelBlock = 1024;

/// A pass of fewer blocks runs on the calling thread alone: waking the
/// other threads costs microseconds (more on a loaded machine), about the
/// work of a few blocks. The blocks, hence the results, are the same.
inline constexpr std::size_t kMinParallelBlocks = 4;

/// Threads of the parallel passes: n > 0 exactly n, 0 every core (the
/// default). Process-wide.
void set_thread_count(int n);
/// The threads the next pass will use.
int thread_count();

/// A non-owning reference to a callable `void(std::size_t first, std::size_t
/// last)`: one indirect call per block, no allocation.
class BlockFn {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, BlockFn>)
      BlockFn(F& f)  // NOLINT(google-explicit-constructor): an argument adaptor
      : object_(static_cast<void*>(&f)),
        call_([](void* o, std::size_t a, std::size_t b) { (*static_cast<F*>(o))(a, b); }) {}
  void operator()(std::size_t first, std::size_t last) const { call_(object_, first, last); }

 private:
  void* object_;
  void (*call_)(void*, std::size_t, std::size_t);
};

/// Calls body(first, last) for each block [b·block, min(n, (b+1)·block)) of
/// [0, n), the blocks spread over thread_count() threads. Blocks must write
/// disjoint outputs. An exception thrown in a block (an interrupt) reaches
/// the caller: on several threads once the pass is over, that of the lowest
/// block; on one thread at once. So the poll of rift/core/interrupt.hpp may
/// be used inside a block.
void parallel_blocks(std::size_t n, std::size_t block, BlockFn body);

/// f(i) for every i in [0, n), in parallel blocks of `block` items.
template <class F>
void parallel_for(std::size_t n, F&& f, std::size_t block = kParallelBlock) {
  auto run = [&f](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
      f(i);
  };
  parallel_blocks(n, block, run);
}

/// f(i) for every i in [0, n), in parallel blocks of `block` items, for the
/// flat sweeps over vertices (the integrators'): f should
/// capture raw pointers and values by copy. Each block runs on its own
/// copy of f, inlined into the loop. Why: Eigen stores its vectors through
/// SIMD types that may alias anything, so a loop reading its arrays'
/// addresses through a closure in memory (captured by reference, or a
/// std::vector's data pointer) loads every one again after each store. The
/// RK4 sweeps took 90 instructions a vertex so, where copies in registers
/// need a third of that.
template <class F>
void parallel_sweep(std::size_t n, const F& f, std::size_t block = kParallelBlock) {
  auto run = [&f](std::size_t first, std::size_t last) RIFT_FLATTEN {
    const F local = f;
    for (std::size_t i = first; i < last; ++i)
      local(i);
  };
  parallel_blocks(n, block, run);
}

namespace detail {
/// Per calling thread: room for `blocks` partial sums (grown, never shrunk,
/// so a warm pass allocates nothing).
std::span<Real> partial_sums(std::size_t blocks);
}  // namespace detail

/// Σ term(i) for i in [0, n): each block sums its items in order, then the
/// partial sums are added in block order. The result depends on n and
/// `block` only, never on the thread count.
template <class F>
Real parallel_sum(std::size_t n, F&& term, std::size_t block = kParallelBlock) {
  const std::size_t blocks = (n + block - 1) / block;
  if (blocks <= 1) {
    Real s = 0;
    for (std::size_t i = 0; i < n; ++i)
      s += term(i);
    return s;
  }
  const std::span<Real> partial = detail::partial_sums(blocks);
  auto run = [&](std::size_t first, std::size_t last) {
    Real s = 0;
    for (std::size_t i = first; i < last; ++i)
      s += term(i);
    partial[first / block] = s;
  };
  parallel_blocks(n, block, run);
  Real total = 0;
  for (Real p : partial)
    total += p;
  return total;
}

}  // namespace rift
