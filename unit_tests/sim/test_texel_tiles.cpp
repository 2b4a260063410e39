#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/inline_math.h"
#include "lrsvo/sim/texel_tiles.h"

namespace lrsvo {
namespace {

constexpr double kBase_m = 0.01;

// Affine in x, y and the footprint: bilinear interpolation within a level and
// the blend between levels (linear in the footprint) both reproduce it
// exactly, so every sample has a hand-computable value.
float affine(double x, double y, double footprint_m) {
  return static_cast<float>(3.0 * x - 2.0 * y + 100.0 * footprint_m);
}

// A region around each point, for its footprint alone.
std::vector<TexelRegion> regionsAround(const std::vector<Eigen::Vector2d>& points,
                                       const std::vector<float>& footprints_m) {
  std::vector<TexelRegion> regions(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    regions[i] = {Eigen::AlignedBox2d(points[i], points[i]), footprints_m[i], footprints_m[i]};
  return regions;
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
  tiles.require(regionsAround(points, footprints), 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Footprints finer than the base texel read the base level.
    const double expected = affine(points[i].x(), points[i].y(), std::max<double>(footprints[i], kBase_m));
    ASSERT_NEAR(tiles.sample(points[i].x(), points[i].y(), footprints[i]), expected, 2e-3)
        << "at (" << points[i].x() << ", " << points[i].y() << "), footprint " << footprints[i];
  }
}

// A sample outside the tiles the last require() listed is computed on the
// spot: the same value, bit for bit, as from the cache.
TEST(TexelTiles, SamplesOutsideTheRequiredTilesHaveTheCachedValue) {
  // Not affine: bilinear interpolation does not reproduce it, so a wrong texel would show.
  auto wavy = [](double x, double y, double footprint_m) {
    return static_cast<float>(std::sin(7.0 * x) * std::cos(5.0 * y) + footprint_m);
  };
  TexelTiles tiles(wavy, kBase_m);
  const std::vector<Eigen::Vector2d> far = {{50.0, -50.0}, {-30.1, 20.2}, {0.123, -7.77}};
  const std::vector<float> footprints = {0.02f, 0.015f, 0.3f};
  tiles.require(regionsAround({Eigen::Vector2d(0.1, 0.1)}, {0.02f}), 1);
  std::vector<float> uncached;
  for (std::size_t i = 0; i < far.size(); ++i) uncached.push_back(tiles.sample(far[i].x(), far[i].y(), footprints[i]));
  tiles.require(regionsAround(far, footprints), 1);
  for (std::size_t i = 0; i < far.size(); ++i)
    EXPECT_EQ(tiles.sample(far[i].x(), far[i].y(), footprints[i]), uncached[i]) << "point " << i;
  // A region spanning several tiles and levels: every sample inside it reads the cache (same values again).
  tiles.require({{Eigen::AlignedBox2d(Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(2.0, 1.5)), 0.01f, 0.05f}}, 2);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-1.0, 2.0), y(-1.0, 1.5), footprint(0.01, 0.05);
  for (int i = 0; i < 200; ++i) {
    const double px = x(rng), py = y(rng), f = footprint(rng);
    const float cached = tiles.sample(px, py, f);
    tiles.require({}, 1);  // nothing listed: the same sample, computed directly
    ASSERT_EQ(tiles.sample(px, py, f), cached);
    tiles.require({{Eigen::AlignedBox2d(Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(2.0, 1.5)), 0.01f, 0.05f}}, 2);
  }
}

// The tiles' layout in memory (texels along x or along y side by side) is
// the renderer's choice for speed: samples are the same bit for bit in
// either, after tiles are transposed from one to the other, and where a new
// tile of one layout takes its coarser nodes from a cached tile of the other.
TEST(TexelTiles, SamplesDoNotDependOnTheLayout) {
  auto wavy = [](double x, double y, double footprint_m) {
    return static_cast<float>(std::sin(7.0 * x) * std::cos(5.0 * y) + 10.0 * footprint_m);
  };
  const Eigen::AlignedBox2d area(Eigen::Vector2d(-1.3, -0.4), Eigen::Vector2d(0.9, 1.7));
  const TexelRegion fine{area, 0.011f, 0.019f}, coarse{area, 0.021f, 0.039f};  // levels 0 and 1
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> x(-1.3, 0.9), y(-0.4, 1.7), footprint(0.011, 0.019);
  std::vector<Eigen::Vector3d> points(3000);
  for (Eigen::Vector3d& p : points) p = Eigen::Vector3d(x(rng), y(rng), footprint(rng));
  auto samples = [&](const TexelTiles& tiles) {
    std::vector<float> values;
    for (const Eigen::Vector3d& p : points) values.push_back(tiles.sample(p.x(), p.y(), p.z()));
    return values;
  };
  TexelTiles alongX(wavy, kBase_m), mixed(wavy, kBase_m), switched(wavy, kBase_m);
  alongX.require({coarse}, 2, Eigen::Vector2d(1.0, 0.2));
  alongX.require({fine}, 2, Eigen::Vector2d(1.0, 0.2));
  const std::vector<float> reference = samples(alongX);
  // Level 1 cached along x and not listed again; level 0 made along y, from level 1's nodes.
  mixed.require({coarse}, 2, Eigen::Vector2d(1.0, 0.2));
  mixed.require({fine}, 2, Eigen::Vector2d(0.3, -1.0));
  // Both levels made along x, then listed for an image whose rows run along y: transposed.
  switched.require({coarse, fine}, 2, Eigen::Vector2d(1.0, 0.0));
  switched.require({coarse, fine}, 2, Eigen::Vector2d(0.0, 1.0));
  for (const TexelTiles* tiles : {&mixed, &switched}) {
    const std::vector<float> values = samples(*tiles);
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(values[i]), std::bit_cast<std::uint32_t>(reference[i])) << "point " << i;
  }
  // A heading just past the diagonal keeps the layout (no switching back and forth); well past it switches.
  const std::pair<double, bool> headings[] = {{10.0, false}, {46.0, false}, {48.0, false}, {52.0, true},
                                              {44.0, true},  {42.0, true},  {38.0, false}, {-95.0, true}};
  for (const auto& [heading_deg, alongY] : headings) {
    const double a = heading_deg * std::numbers::pi / 180.0;
    switched.require({fine}, 2, Eigen::Vector2d(std::cos(a), std::sin(a)));
    EXPECT_EQ(switched.tilesAlongY(), alongY) << "at heading " << heading_deg;
    const std::vector<float> values = samples(switched);
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(values[i]), std::bit_cast<std::uint32_t>(reference[i]))
          << "point " << i << " at heading " << heading_deg;
  }
}

// sampleMany() gives sample()'s values bit for bit: runs of neighbouring
// pixels (the renderer's case, mostly four at one level), runs crossing a
// level or a tile, points outside the listed tiles, footprints finer than the
// base texel or beyond the coarsest level, and lengths that leave a remainder;
// with the tiles laid out along x and along y.
void checkSampleManyGivesSample(const Eigen::Vector2d& rowDirection) {
  auto wavy = [](double x, double y, double footprint_m) {
    return static_cast<float>(std::sin(7.0 * x) * std::cos(5.0 * y) + 10.0 * footprint_m);
  };
  TexelTiles tiles(wavy, kBase_m);
  tiles.require({{Eigen::AlignedBox2d(Eigen::Vector2d(-2.0, -1.0), Eigen::Vector2d(1.0, 2.0)), 0.004f, 0.2f}}, 2,
                rowDirection);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> start(-2.5, 1.5), step(-0.03, 0.03), logFootprint(-6.0, -1.5);
  std::vector<double> x, y;
  std::vector<float> footprints;
  for (int run = 0; run < 400; ++run) {  // runs of 1..40 points along a line, the footprint drifting
    double px = start(rng), py = start(rng), f = std::exp(logFootprint(rng));
    const double dx = step(rng), dy = step(rng), growth = 1.0 + step(rng);
    for (int i = 0, length = 1 + run % 40; i < length; ++i, px += dx, py += dy, f *= growth)
      x.push_back(px), y.push_back(py), footprints.push_back(static_cast<float>(f));
  }
  for (float extreme : {1e-9f, 5e9f, 0.0f, std::numeric_limits<float>::infinity()})
    for (int i = 0; i < 4; ++i) x.push_back(0.1 * i), y.push_back(0.2), footprints.push_back(i == 2 ? extreme : 0.02f);
  const int count = static_cast<int>(x.size());
  std::vector<float> many(count);
  tiles.sampleMany(x.data(), y.data(), footprints.data(), count, many.data());
  std::cout << "[ info     ] " << count << " points, AVX2 path "
            << (TexelTiles::simd() ? "on" : "off (not in this CPU)") << "\n";
  for (int i = 0; i < count; ++i) {
    const float one = tiles.sample(x[i], y[i], footprints[i]);
    ASSERT_EQ(std::bit_cast<std::uint32_t>(many[i]), std::bit_cast<std::uint32_t>(one))
        << "point " << i << " at (" << x[i] << ", " << y[i] << "), footprint " << footprints[i];
  }
  // Calls of any length, shorter than the AVX2 path's look-ahead or not, write their points and no others.
  for (const int length : {0, 1, 3, 4, 5, 31, 64, 127, 129, 513}) {
    std::vector<float> part(length + 1, -1.0f);
    tiles.sampleMany(x.data() + 7, y.data() + 7, footprints.data() + 7, length, part.data());
    for (int i = 0; i < length; ++i)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(part[i]), std::bit_cast<std::uint32_t>(many[7 + i]))
          << "point " << i << " of " << length;
    EXPECT_EQ(part[length], -1.0f) << "written past " << length << " points";
  }
}

TEST(TexelTiles, SampleManyGivesSampleBitForBit) {
  for (const Eigen::Vector2d& rows : {Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 1.0)}) {
    SCOPED_TRACE(rows.x() == 1.0 ? "tiles along x" : "tiles along y");
    checkSampleManyGivesSample(rows);
  }
}

TEST(TexelTiles, RejectsANonPositiveBaseTexel) { EXPECT_THROW(TexelTiles(affine, 0.0), Error); }

// The renderer's inline frexp gives the library's result bit for bit, and
// floorIndex the library's floor: zeros of both signs, subnormals, integers
// and halves, huge values, infinities, NaN, and random values over every
// magnitude (floorIndex where it is defined, below 2^62).
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
    if (std::abs(x) < 0x1p62) {
      EXPECT_EQ(static_cast<double>(floorIndex(x)), std::floor(x)) << x;
    }
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
  EXPECT_TRUE(std::isnan(frexpInline(nan, &unused)));
}

}  // namespace
}  // namespace lrsvo
