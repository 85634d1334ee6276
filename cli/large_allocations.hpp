// Large allocations of a simulator's process in transparent huge pages
// (large_allocations.cpp replaces the global operator new and delete).
#pragma once

namespace rift::cli {

/// True when this process's operator new advises large blocks for huge
/// pages (false in sanitizer builds). run() calls it, which also links the
/// replacement into every executable that uses the command line.
bool large_allocations_in_huge_pages();

/// Makes malloc give every block of kHugePageAdviceBytes or more back to the
/// kernel when it is freed (see large_allocations.cpp). run() calls it first.
void give_large_blocks_back_when_freed();

}  // namespace rift::cli
