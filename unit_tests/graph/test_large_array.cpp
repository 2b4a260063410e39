// LargeArray (graph/large_array.h): arrays under 2 MiB from operator new,
// larger ones in whole 2 MiB units aligned to 2 MiB; either way an ordinary
// vector that keeps its values through growth and copies.

#include <cstdint>
#include <numeric>

#include <gtest/gtest.h>

#include "lrsvo/graph/large_array.h"

namespace lrsvo::test {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

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

}  // namespace
}  // namespace lrsvo::test
