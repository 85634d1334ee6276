// Ctrl-C as a request, not a kill: SIGINT only raises a flag, and the long
// loops of the runtime (force passes, criteria, integrator stages) poll it at
// coarse granularity and throw `Interrupted`, so a run stops within a fraction
// of a second even inside a long step, and files are never cut mid-write.
//
// Polling is one relaxed atomic load: cheap enough for every element of a
// criterion pass or every few thousand matches of a force pass. Never poll
// (throw) inside a raw OpenMP region; inside a block of rift::parallel_blocks
// (core/parallel.hpp) it is fine: the exception reaches the caller.
#pragma once

#include <atomic>
#include <stdexcept>

namespace rift {

namespace detail {
// Lock-free, hence async-signal-safe to store from a signal handler.
inline std::atomic<bool> g_interrupt_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);
}  // namespace detail

/// Thrown by throw_if_interrupted(): the current step was abandoned part-way
/// (its state is not a finished step; earlier frames are complete).
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

/// Async-signal-safe: what the SIGINT handler calls.
inline void request_interrupt() noexcept {
  detail::g_interrupt_requested.store(true, std::memory_order_relaxed);
}
inline void clear_interrupt() noexcept {
  detail::g_interrupt_requested.store(false, std::memory_order_relaxed);
}
inline bool interrupt_requested() noexcept {
  return detail::g_interrupt_requested.load(std::memory_order_relaxed);
}
/// The poll of the long loops.
inline void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted();
}

/// While alive, SIGINT requests an interrupt instead of killing the process;
/// the previous handler comes back on destruction. Clears the flag on entry.
class InterruptHandler {
 public:
  InterruptHandler();
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

 private:
  void (*previous_)(int);
};

}  // namespace rift
