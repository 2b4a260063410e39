#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "graph/error.h"
#include "sim/inline_math.h"
#include "sim/texel_tiles.h"

namespace lrsvo {
namespace {

constexpr double kBase_m = 0.01;

// Affine in x, y and the footprint: bilinear interpolation within a level and
// the blend between levels (linear in the footprint) both reproduce it
// exactly, so every sample has a hand-computable value.
float affine(double x, double y, double footprint_m) {
  return static_cast<float>(3.0 * x - 2.0 * y + 100.0 * footprint_m);
}

// Every one of these points will be sampled.
void requireAll(TexelTiles& tiles, const std::vector<Eigen::Vector2d>& points, const std::vector<float>& footprints_m,
                int threads) {
  tiles.require(
      points.size(),
      [&](std::size_t i, Eigen::Vector2d& xy, float& footprint_m) {
        xy = points[i];
        footprint_m = footprints_m[i];
        return true;
      },
      threads);
}

TEST(TexelTiles, SamplesReproduceAnAffineTextureAcrossTilesLevelsAndNegativeCoordinates) {
  TexelTiles tiles(affine, kBase_m);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> position(-7.0, 5.0), logFootprint(-8.0, -1.0);  // 0.3 mm .. 0.37 m
  std::vector<Eigen::Vector2d> points;
  std::vector<float> footprints;
  for (int i = 0; i < 2000; ++i) {
    points.emplace_back(position(rng), position(rng));
    footprints.push_back(static_cast<float>(std::exp(logFootprint(rng))));
  }
  requireAll(tiles, points, footprints, 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Footprints finer than the base texel read the base level.
    const double expected = affine(points[i].x(), points[i].y(), std::max<double>(footprints[i], kBase_m));
    ASSERT_NEAR(tiles.sample(points[i].x(), points[i].y(), footprints[i]), expected, 2e-3)
        << "at (" << points[i].x() << ", " << points[i].y() << "), footprint " << footprints[i];
  }
}

TEST(TexelTiles, SamplingOutsideTheLastRequiredTilesThrows) {
  TexelTiles tiles(affine, kBase_m);
  requireAll(tiles, {Eigen::Vector2d(0.1, 0.1)}, {0.02f}, 1);
  EXPECT_NO_THROW(tiles.sample(0.1, 0.1, 0.02));
  EXPECT_THROW(tiles.sample(50.0, -50.0, 0.02), Error);  // far from any listed tile
  requireAll(tiles, {Eigen::Vector2d(-30.0, 20.0)}, {0.02f}, 1);
  EXPECT_THROW(tiles.sample(0.1, 0.1, 0.02), Error);  // listed by the previous image only
  EXPECT_NEAR(tiles.sample(-30.0, 20.0, 0.02), affine(-30.0, 20.0, 0.02), 2e-3);
}

TEST(TexelTiles, RejectsANonPositiveBaseTexel) { EXPECT_THROW(TexelTiles(affine, 0.0), Error); }

// The renderer's inline floor and frexp give the library's results bit for
// bit: zeros of both signs, subnormals, integers and halves, huge values,
// infinities, NaN, and random values over every magnitude.
TEST(InlineMath, FloorAndFrexpEqualTheLibrarysBitForBit) {
  using Limits = std::numeric_limits<double>;
  std::vector<double> values = {
      0.0, 0.5, 1.0, 2.5, 0x1p62, 0x1p62 - 1024.0, 1e300, Limits::denorm_min(), Limits::min(), Limits::infinity()};
  for (std::size_t i = 0, n = values.size(); i < n; ++i) values.push_back(-values[i]);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1070, 1020);
  std::uniform_real_distribution<double> texelIndex(-1e4, 1e4);
  for (int i = 0; i < 100000; ++i) values.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  for (int i = 0; i < 100000; ++i) values.push_back(texelIndex(rng));
  for (double x : values) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(floorInline(x)), std::bit_cast<std::uint64_t>(std::floor(x))) << x;
    int expected = 0, actual = 0;
    const double libraryMantissa = std::frexp(x, &expected);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(frexpInline(x, &actual)), std::bit_cast<std::uint64_t>(libraryMantissa))
        << x;
    if (std::isfinite(x)) {
      EXPECT_EQ(actual, expected) << x;
    }
  }
  const double nan = Limits::quiet_NaN();
  int unused = 0;
  EXPECT_TRUE(std::isnan(floorInline(nan)));
  EXPECT_TRUE(std::isnan(frexpInline(nan, &unused)));
}

}  // namespace
}  // namespace lrsvo
