// Counts the heap allocations of a test binary. A binary that links
// allocation_watch.cpp (rift_add_allocation_test in tests/CMakeLists.txt)
// has its global operator new replaced: every request is counted, and the
// largest single request is kept, so a test can assert "this step allocates
// nothing" or "this reader never asks for more than what it has read".
#pragma once

#include <cstddef>

namespace rift::test_support {

/// Allocations made by the whole process so far.
long allocation_count();

/// Forgets the largest request seen so far.
void reset_largest_allocation();

/// The largest single request since the last reset.
std::size_t largest_allocation();

}  // namespace rift::test_support
