// LargeArray (graph/large_array.h): arrays under 2 MiB from operator new,
// larger ones aligned to 2 MiB, resident only where used and returned to the
// system when freed; either way an ordinary vector that keeps its values
// through growth and copies.

#include <cstdint>
#include <fstream>
#include <numeric>

#include <unistd.h>

#include <gtest/gtest.h>

#include "lrsvo/graph/large_array.h"

namespace lrsvo::test {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// The process' resident memory in bytes (Linux /proc), 0 where unknown.
std::size_t residentBytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t total = 0, resident = 0;
  if (!(statm >> total >> resident)) return 0;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

TEST(LargeArray, LargeArraysAreAlignedToWholeHugePages) {
  LargeArray<double> large(kHugePage / sizeof(double) + 1);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePage, 0u);
  std::iota(large.begin(), large.end(), 0.0);
  EXPECT_EQ(large.back(), static_cast<double>(large.size() - 1));
}

TEST(LargeArray, KeepsItsValuesThroughGrowthAcrossTheThresholdAndCopies) {
  LargeArray<int> values;
  const int count = static_cast<int>(kHugePage / sizeof(int)) * 3;  // grows from small to three huge pages
  for (int i = 0; i < count; ++i) values.push_back(i);
  const LargeArray<int> copy = values;
  ASSERT_EQ(copy.size(), static_cast<std::size_t>(count));
  for (int i = 0; i < count; i += 4099) EXPECT_EQ(copy[static_cast<std::size_t>(i)], i);
  EXPECT_EQ(copy.back(), count - 1);
}

// An array one page past 2 MiB, every byte written: the whole 2 MiB may be one
// huge page, the page past it must be a small one, so it adds 2 MiB and a page
// to the resident memory (a 2 MiB unit for the tail would add 4 MiB). 3 MiB
// leaves room for the test's own allocations. Freed, all of it leaves.
TEST(LargeArray, IsResidentOnlyWhereUsedAndLeavesWhenFreed) {
  if (residentBytes() == 0) GTEST_SKIP() << "no /proc/self/statm";
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t before = residentBytes();
  {
    LargeArray<char> array(kHugePage + page, 1);
    const std::size_t used = residentBytes();
    EXPECT_GE(used, before + kHugePage);
    EXPECT_LT(used, before + 3 * (kHugePage / 2));
  }
  EXPECT_LT(residentBytes(), before + kHugePage / 2);
}

}  // namespace
}  // namespace lrsvo::test
