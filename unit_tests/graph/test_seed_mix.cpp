// The one seeding rule: streams derived from neighbouring seeds share nothing.
#include <cstdint>
#include <set>

#include <gtest/gtest.h>

#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

// With seed + k, seed s's stream k + 1 would be seed s + 1's stream k, so two
// runs one seed apart would repeat each other's draws frame by frame. Every
// (seed, stream, index) of a neighbourhood must give its own seed.
TEST(SeedMix, NeighbouringSeedsAndIndicesGiveDistinctStreams) {
  std::set<std::uint64_t> seen;
  int derived = 0;
  for (std::uint64_t seed = 0; seed < 16; ++seed)
    for (std::uint64_t stream : {0ULL, 1ULL, 0x706f7365ULL})
      for (std::uint64_t index = 0; index < 64; ++index, ++derived) seen.insert(mixSeed(seed, stream, index));
  EXPECT_EQ(static_cast<int>(seen.size()), derived);
}

TEST(SeedMix, IsAFunctionOfItsInputsAlone) {
  EXPECT_EQ(mixSeed(7, 1, 2), mixSeed(7, 1, 2));
  EXPECT_NE(mixSeed(7, 1, 2), mixSeed(7, 2, 1));
  SplitMix64 generator(42);
  for (std::uint64_t n = 1; n <= 5; ++n) EXPECT_EQ(generator(), SplitMix64::at(42, n));
}

}  // namespace
}  // namespace lrsvo
