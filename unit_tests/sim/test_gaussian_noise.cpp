#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/sim/gaussian_noise.h"

namespace lrsvo {
namespace {

constexpr std::uint64_t kNoiseKey = 0x1234abcd;

// A million draws: the moments and tails of N(0, 1) to their sampling error
// (standard errors 1e-3 for the mean, 1.4e-3 for the variance, 5e-3 for the
// kurtosis, 2e-4 for the fraction beyond 2 sigma; bounds at about 5 of them),
// no correlation between neighbours (1e-3), bounded by the table's last quantile.
TEST(GaussianNoise, DrawsHaveTheMomentsAndTailsOfAStandardNormal) {
  constexpr int kDraws = 1'000'000;
  double sum = 0.0, squares = 0.0, fourths = 0.0, lagged = 0.0, largest = 0.0;
  int beyondTwo = 0;
  float previous = standardNormalDraw(kNoiseKey, 0);
  for (int i = 1; i <= kDraws; ++i) {
    const double x = standardNormalDraw(kNoiseKey, static_cast<std::uint64_t>(i));
    sum += x, squares += x * x, fourths += x * x * x * x, lagged += x * previous;
    beyondTwo += std::abs(x) > 2.0;
    largest = std::max(largest, std::abs(x));
    previous = static_cast<float>(x);
  }
  EXPECT_NEAR(sum / kDraws, 0.0, 5e-3);
  EXPECT_NEAR(squares / kDraws, 1.0, 7e-3);
  EXPECT_NEAR(fourths / kDraws, 3.0, 0.03);
  EXPECT_NEAR(static_cast<double>(beyondTwo) / kDraws, 0.0455, 1e-3);
  EXPECT_NEAR(lagged / kDraws, 0.0, 5e-3);
  EXPECT_LT(largest, 4.5);
  EXPECT_GT(largest, 4.0);  // the table reaches into the tails
}

TEST(GaussianNoise, AddingGivesTheDrawsOfEachIndexWhateverTheStartAndLength) {
  for (const std::uint64_t first : {0ULL, 1ULL, 6ULL, 1'000'003ULL})
    for (const int count : {0, 1, 3, 4, 9, 64}) {
      std::vector<float> values(count, 10.0f);
      addGaussianNoise(values.data(), count, 2.5, kNoiseKey, first);
      for (int i = 0; i < count; ++i)
        ASSERT_EQ(values[i], 10.0f + 2.5f * standardNormalDraw(kNoiseKey, first + i))
            << "first " << first << ", count " << count << ", i " << i;
    }
}

TEST(GaussianNoise, AnotherKeyGivesOtherDraws) {
  int same = 0;
  for (std::uint64_t i = 0; i < 1000; ++i)
    same += standardNormalDraw(kNoiseKey, i) == standardNormalDraw(kNoiseKey + 1, i);
  EXPECT_LT(same, 5);  // equal only by chance: 1 in 2^16 per pair
}

}  // namespace
}  // namespace lrsvo
