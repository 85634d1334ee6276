// The benchmark programs allocate as `rift` does: their global operator new
// is the command line's (cli/large_allocations.cpp), which advises every
// large block for transparent huge pages, and malloc gives large blocks back
// when they are freed. So a benchmark measures the program users run: a
// 10^6-vertex cloth's match caches, groups and scratch in 2 MiB pages, as
// `rift run` has them, not in 4 KiB ones (docs/performance.md, "The
// benchmarks allocate as rift does").
#include "cli/large_allocations.hpp"

namespace {

// Set before main, so before any benchmark allocates.
[[maybe_unused]] const bool kLargeBlocksInHugePages = [] {
  rift::cli::give_large_blocks_back_when_freed();
  return rift::cli::large_allocations_in_huge_pages();
}();

}  // namespace
