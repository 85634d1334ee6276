// The executables of the command line advise every large allocation for
// transparent huge pages (cli/large_allocations.cpp): a block of 4 MiB or
// more starts on a 2 MiB boundary, and the kernel holds its mapping as one
// that may be backed by huge pages (VmFlags "hg" in /proc/self/smaps).
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli/large_allocations.hpp"

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;

/// The VmFlags of the mapping holding `address`, or "" when /proc says nothing.
std::string vm_flags_at(const void* address) {
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= a && a < end;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

bool kernel_has_huge_pages() {
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

TEST(LargeAllocations, StartOnAHugePageAndAreAdvisedForHugePages) {
  if (!rift::cli::large_allocations_in_huge_pages()) GTEST_SKIP() << "a sanitizer's allocator";
  for (std::size_t bytes : {std::size_t{4} << 20, (std::size_t{9} << 20) + 24}) {
    std::vector<char> block(bytes);
    const auto at = reinterpret_cast<std::uintptr_t>(block.data());
    EXPECT_EQ(at % kHugePage, 0u) << bytes << " bytes";
    if (!kernel_has_huge_pages()) continue;
    const std::string flags = vm_flags_at(block.data() + bytes - 1);
    ASSERT_FALSE(flags.empty());
    EXPECT_NE(flags.find(" hg"), std::string::npos) << bytes << " bytes: " << flags;
  }
  // Arrays and sized deletes go through the same pair.
  auto array = std::make_unique<double[]>(std::size_t{1} << 20);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(array.get()) % kHugePage, 0u);
  array[(std::size_t{1} << 20) - 1] = 1.0;
  EXPECT_EQ(array[(std::size_t{1} << 20) - 1], 1.0);
}

TEST(LargeAllocations, SmallAllocationsAreMallocsOwn) {
  // Well below the threshold: no 2 MiB alignment forced on a small block
  // (two of them cannot both start on one).
  auto a = std::make_unique<char[]>(64);
  auto b = std::make_unique<char[]>(64);
  const auto pa = reinterpret_cast<std::uintptr_t>(a.get());
  const auto pb = reinterpret_cast<std::uintptr_t>(b.get());
  EXPECT_FALSE(pa % kHugePage == 0 && pb % kHugePage == 0);
}

// Once a large block was mapped and freed, glibc's heap would serve the next
// blocks below the freed one's size and keep their pages when they are
// freed; with the threshold fixed (give_large_blocks_back_when_freed), a
// block of 4 MiB or more is still a mapping of its own (mallinfo2's hblkhd
// counts the bytes of such mappings).
TEST(LargeAllocations, LargeBlocksAreMappingsOfTheirOwnAfterALargerOneWasFreed) {
  if (!rift::cli::large_allocations_in_huge_pages()) GTEST_SKIP() << "a sanitizer's allocator";
#if defined(__GLIBC__)
  rift::cli::give_large_blocks_back_when_freed();
  // The heap's free top serves any block that fits in it, mapped or not:
  // given back first, as at the start of a process.
  malloc_trim(0);
  {
    std::vector<char> larger(std::size_t{40} << 20, 1);
    EXPECT_EQ(larger.back(), 1);
  }
  const std::size_t before = mallinfo2().hblkhd;
  std::vector<char> block(std::size_t{6} << 20, 2);
  EXPECT_EQ(block.back(), 2);
  EXPECT_GE(mallinfo2().hblkhd, before + block.size());
#else
  GTEST_SKIP() << "not glibc";
#endif
}

}  // namespace
