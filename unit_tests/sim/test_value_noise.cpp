#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include "lrsvo/sim/cpu_features.h"
#include "lrsvo/sim/ground_texture.h"
#include "lrsvo/sim/value_noise.h"

namespace lrsvo {
namespace {

std::uint64_t bitsOf(double value) { return std::bit_cast<std::uint64_t>(value); }

// fractalRow() gives fractal()'s values bit for bit: rows of texels at any
// spacing (a fraction of a lattice cell to several cells), negative
// coordinates, footprints that fade some octaves or none (0), and lengths
// that leave a remainder for the scalar tail.
TEST(ValueNoise, FractalRowGivesFractalBitForBit) {
  const Octaves octaves[] = {{0.02, 1.28, 1.0}, {4.0, 64.0, 0.7}, {0.5, 4.0, 0.8}, {0.04, 1.28, 0.85}};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> start(-3000.0, 3000.0), logSpacing(-5.0, 1.0);
  auto rowMemo = std::make_unique<NoiseMemo>(), pointMemo = std::make_unique<NoiseMemo>();
  int compared = 0;
  for (int run = 0; run < 300; ++run) {
    const Octaves& o = octaves[run % 4];
    const double spacing = std::exp(logSpacing(rng)), y = start(rng);
    const double footprint = run % 7 == 0 ? 0.0 : spacing;
    const int count = 1 + run % 70;
    std::vector<double> x(count), row(count);
    const double x0 = start(rng);
    for (int n = 0; n < count; ++n) x[n] = x0 + n * spacing;
    fractalRow(x.data(), y, count, o, footprint, 17u + run % 3, *rowMemo, row.data());
    for (int n = 0; n < count; ++n, ++compared)
      ASSERT_EQ(bitsOf(row[n]), bitsOf(fractal(x[n], y, o, footprint, 17u + run % 3, *pointMemo)))
          << "run " << run << ", point " << n << " at (" << x[n] << ", " << y << ")";
  }
  std::cout << "[ info     ] " << compared << " points, AVX2 path " << (cpuHasAvx2() ? "on" : "off (not in this CPU)")
            << "\n";
}

// The memo only spares work: a value is the same whatever the memo held before.
TEST(ValueNoise, FractalDoesNotDependOnTheMemo) {
  const Octaves octaves{0.02, 2.56, 1.0};
  auto warm = std::make_unique<NoiseMemo>();
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  for (int i = 0; i < 2000; ++i) {
    const double x = coordinate(rng), y = coordinate(rng);
    const double warmed = fractal(x, y, octaves, 0.03, 6u, *warm);
    auto fresh = std::make_unique<NoiseMemo>();
    ASSERT_EQ(bitsOf(warmed), bitsOf(fractal(x, y, octaves, 0.03, 6u, *fresh))) << "at (" << x << ", " << y << ")";
  }
}

// No value exceeds fractalBound(), and the bound is not loose by much (it
// is what lets the ground texture skip a hedge's width far from any hedge).
TEST(ValueNoise, FractalStaysWithinItsBound) {
  const Octaves octaves{0.5, 4.0, 0.8};
  const double bound = fractalBound(octaves);
  auto memo = std::make_unique<NoiseMemo>();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-1e4, 1e4);
  double largest = 0.0;
  for (int i = 0; i < 200000; ++i)
    largest = std::max(largest, std::abs(fractal(coordinate(rng), coordinate(rng), octaves, 0.0, 11u, *memo)));
  std::cout << "[ info     ] largest |fractal| " << largest << " of the bound " << bound << "\n";
  EXPECT_LE(largest, bound);
  EXPECT_GT(largest, 0.5 * bound);
}

// The ground texture's cached texels (filled a row at a time) are ground()
// at their nodes, bit for bit: over small fields, so that the rows cross
// field edges, tracks, hedges and verges.
TEST(GroundTexture, CachedTexelsAreGroundAtTheirNodes) {
  GroundTextureOptions options;
  options.fieldSize_m = 12.0;
  options.trackProbability = 0.3;
  options.hedgeProbability = 0.5;
  const GroundTexture texture(options);
  const double texel_m = 0.04;  // level 2: a footprint of exactly 4 cm reads this level's nodes alone
  SurfaceRegions seen;
  seen.ground.push_back({Eigen::AlignedBox2d(Eigen::Vector2d(-10.0, 3.0), Eigen::Vector2d(14.0, 9.0)),
                         static_cast<float>(texel_m), static_cast<float>(texel_m)});
  texture.prepare(seen, 2);
  int compared = 0;
  for (int iy = 80; iy < 220; iy += 7) {
    for (int ix = -240; ix < 340; ix += 3, ++compared) {
      SurfaceHit hit;
      hit.point = Eigen::Vector3d(ix * texel_m, iy * texel_m, 0.0);
      ASSERT_EQ(std::bit_cast<std::uint32_t>(texture.grey(hit, texel_m)),
                std::bit_cast<std::uint32_t>(texture.ground(hit.point.x(), hit.point.y(), texel_m)))
          << "node (" << ix << ", " << iy << ")";
    }
  }
  EXPECT_GT(compared, 3000);
}

}  // namespace
}  // namespace lrsvo
