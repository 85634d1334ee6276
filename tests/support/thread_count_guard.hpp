#pragma once

#include "rift/core/parallel.hpp"

namespace rift::test {

/// Restores the default thread count (all cores) when a test that sets its
/// own leaves, so that later tests of the same binary run as configured.
struct ThreadCountGuard {
  ThreadCountGuard() = default;
  ThreadCountGuard(const ThreadCountGuard&) = delete;
  ThreadCountGuard& operator=(const ThreadCountGuard&) = delete;
  ~ThreadCountGuard() { set_thread_count(0); }
};

}  // namespace rift::test
