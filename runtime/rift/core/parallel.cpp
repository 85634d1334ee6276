// The threads behind parallel_blocks: a small pool of std::threads that sleep
// on a condition variable between passes.
//
// Why not OpenMP: GCC's libgomp makes waiting threads spin (hundreds of
// thousands of iterations) between parallel regions, and its wait policy can
// only be set by environment variables read before main(). On a shared
// machine (load 9 on 2 cores, as measured while this was written) a spinning
// thread steals the core its partner needs: 2 threads ran a small implicit
// beam 15 times slower than 1. Sleeping workers cost a wake-up per pass
// (tens of microseconds), which kMinParallelBlocks keeps small next to the
// work of the pass; a worker first waits awake for at most kSpinRounds
// pauses (spin_until: tens of microseconds, a hundred on CPUs whose pause
// takes 140 cycles), which catches the next pass of a solver whose passes
// come back to back, and gives its core back long before libgomp would.
#include "rift/core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace rift {

namespace {

std::atomic<int> g_requested_threads{0};  // 0: every core

// Asked once: hardware_concurrency() reads a sysfs file on every call.
int hardware_threads() {
  static const int kCores = [] {
    const unsigned cores = std::thread::hardware_concurrency();
    return cores == 0 ? 1 : static_cast<int>(cores);
  }();
  return kCores;
}

// Set while a thread runs a block: a pass started from inside a block runs
// on that thread alone instead of waiting for the busy pool.
thread_local bool t_inside_block = false;

class Pool {
 public:
  ~Pool() { resize(0); }

  /// Runs every block of the pass on `threads` threads (the caller is one).
  void run(std::size_t n, std::size_t block, BlockFn body, int threads) {
    std::unique_lock pass_lock(pass_mutex_, std::try_to_lock);
    if (!pass_lock.owns_lock()) {
      // Another thread of the program is running a pass: do this one alone.
      serial(n, block, body);
      return;
    }
    resize(threads - 1);
    {
      std::lock_guard lock(mutex_);
      n_ = n;
      block_ = block;
      blocks_ = (n + block - 1) / block;
      body_ = &body;
      next_.store(0, std::memory_order_relaxed);
      error_ = nullptr;
      error_block_ = std::numeric_limits<std::size_t>::max();
      busy_.store(workers_.size(), std::memory_order_relaxed);
      ++generation_;
      published_.store(generation_, std::memory_order_release);
    }
    wake_.notify_all();
    work();
    spin_until([&] { return busy_.load(std::memory_order_acquire) == 0; });
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return busy_.load(std::memory_order_relaxed) == 0; });
    body_ = nullptr;
    if (error_) std::rethrow_exception(error_);
  }

  static void serial(std::size_t n, std::size_t block, BlockFn body) {
    const std::size_t blocks = (n + block - 1) / block;
    for (std::size_t b = 0; b < blocks; ++b)
      body(b * block, std::min(n, (b + 1) * block));
  }

 private:
  // Takes blocks until none is left. Blocks go to whichever thread asks
  // first (a descheduled thread does not hold up the pass); which thread runs
  // a block never changes what it writes.
  void work() {
    t_inside_block = true;
    for (;;) {
      const std::size_t b = next_.fetch_add(1, std::memory_order_relaxed);
      if (b >= blocks_) break;
      try {
        (*body_)(b * block_, std::min(n_, (b + 1) * block_));
      } catch (...) {
        std::lock_guard lock(mutex_);
        if (b < error_block_) {  // the lowest block's: the same whatever the threads
          error_block_ = b;
          error_ = std::current_exception();
        }
      }
    }
    t_inside_block = false;
  }

  // Called with pass_mutex_ held (or from the destructor): no pass running.
  void resize(int workers) {
    const auto wanted = static_cast<std::size_t>(std::max(workers, 0));
    if (wanted == workers_.size()) return;
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_)
      t.join();
    workers_.clear();
    {
      std::lock_guard lock(mutex_);
      stop_ = false;
    }
    // A new worker has "seen" the current pass: it waits for the next one
    // (no pass runs now, so generation_ does not move meanwhile).
    for (std::size_t i = 0; i < wanted; ++i)
      workers_.emplace_back([this, seen = generation_] { worker(seen); });
  }

  // Waits at most kSpinRounds pauses for `ready` before the caller falls
  // back to sleeping: the passes of an implicit step come back to back (a PCG
  // iteration is seven passes of microseconds each), and a worker put to
  // sleep between them joins each pass a wake-up late, when the caller has
  // done most of its blocks. Bounded, unlike libgomp's spinning (see the
  // top of this file): on a loaded machine a spinner gives its core back
  // within kSpinRounds pauses.
  template <class Ready>
  static void spin_until(Ready&& ready) {
    for (int i = 0; i < kSpinRounds && !ready(); ++i)
      cpu_pause();
  }

  static void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }

  void worker(std::uint64_t seen) {
    for (;;) {
      spin_until([&] { return published_.load(std::memory_order_acquire) != seen; });
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      lock.unlock();
      work();
      lock.lock();
      if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) done_.notify_one();
    }
  }

  std::mutex pass_mutex_;  // one pass at a time
  std::mutex mutex_;       // everything below
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
  std::atomic<std::size_t> busy_{0};
  // generation_, readable without the lock (by a spinning worker).
  std::atomic<std::uint64_t> published_{0};
  static constexpr int kSpinRounds = 2000;
  // The current pass.
  std::size_t n_ = 0, block_ = 1, blocks_ = 0;
  const BlockFn* body_ = nullptr;
  std::atomic<std::size_t> next_{0};
  std::exception_ptr error_;
  std::size_t error_block_ = 0;
};

Pool& pool() {
  static Pool p;
  return p;
}

}  // namespace

void set_thread_count(int n) {
  g_requested_threads.store(n > 0 ? n : 0, std::memory_order_relaxed);
}

int thread_count() {
  const int n = g_requested_threads.load(std::memory_order_relaxed);
  return n > 0 ? n : hardware_threads();
}

void parallel_blocks(std::size_t n, std::size_t block, BlockFn body) {
  if (n == 0) return;
  const std::size_t blocks = (n + block - 1) / block;
  const int threads = thread_count();
  if (threads <= 1 || blocks < kMinParallelBlocks || t_inside_block) {
    Pool::serial(n, block, body);
    return;
  }
  pool().run(n, block, body, threads);
}

namespace detail {

std::span<Real> partial_sums(std::size_t blocks) {
  thread_local std::vector<Real> sums;
  if (sums.size() < blocks) sums.resize(blocks);
  return {sums.data(), blocks};
}

}  // namespace detail

}  // namespace rift
