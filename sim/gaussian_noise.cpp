#include "lrsvo/sim/gaussian_noise.h"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

constexpr int kQuantileBits = 16;
constexpr int kQuantiles = 1 << kQuantileBits;
using QuantileTable = std::array<float, kQuantiles>;

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// Quantile k at probability (k + 1/2) / 2^16 by Newton's method, outward
// from the median (each starts from its inner neighbour, and Newton's steps
// on the convex lower tail approach the root monotonically); the upper half
// by symmetry; then scaled to unit variance.
std::unique_ptr<QuantileTable> makeQuantiles() {
  auto table = std::make_unique<QuantileTable>();
  const double normalDensityAtZero = 1.0 / std::sqrt(2.0 * std::numbers::pi);
  double x = 0.0, sumOfSquares = 0.0;
  for (int k = kQuantiles / 2 - 1; k >= 0; --k) {
    const double p = (k + 0.5) / kQuantiles;
    for (int step = 0; step < 100; ++step) {
      const double density = normalDensityAtZero * std::exp(-0.5 * x * x);
      const double dx = (normalCdf(x) - p) / density;
      x -= dx;
      if (std::abs(dx) < 1e-13) break;
    }
    (*table)[k] = static_cast<float>(x);
    (*table)[kQuantiles - 1 - k] = static_cast<float>(-x);
    sumOfSquares += 2.0 * x * x;
  }
  const double scale = 1.0 / std::sqrt(sumOfSquares / kQuantiles);
  for (float& q : *table) q = static_cast<float>(q * scale);
  return table;
}

const QuantileTable& quantiles() {
  static const std::unique_ptr<QuantileTable> table = makeQuantiles();
  return *table;
}

}  // namespace

float standardNormalDraw(std::uint64_t key, std::uint64_t index) {
  const std::uint64_t bits = SplitMix64::at(key, index / 4 + 1);
  return quantiles()[(bits >> (kQuantileBits * (index % 4))) & (kQuantiles - 1)];
}

void addGaussianNoise(float* values, int count, double sigma, std::uint64_t key, std::uint64_t first) {
  const QuantileTable& table = quantiles();
  const auto scale = static_cast<float>(sigma);
  for (int i = 0; i < count;) {
    const std::uint64_t n = first + static_cast<std::uint64_t>(i);
    std::uint64_t bits = SplitMix64::at(key, n / 4 + 1) >> (kQuantileBits * (n % 4));
    for (std::uint64_t lane = n % 4; lane < 4 && i < count; ++lane, ++i, bits >>= kQuantileBits)
      values[i] += scale * table[bits & (kQuantiles - 1)];
  }
}

}  // namespace lrsvo
