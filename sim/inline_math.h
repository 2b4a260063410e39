#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace lrsvo {

// std::floor and std::frexp without a call into libm (g++ calls it for both
// unless the target has SSE4.1), bit for bit the same results: the renderer
// runs them several times per pixel.
inline double floorInline(double x) {
  if (!(std::abs(x) < 0x1p62)) return std::floor(x);  // also inf and NaN
  const double truncated = static_cast<double>(static_cast<std::int64_t>(x));
  if (truncated == 0.0) return x < 0.0 ? -1.0 : std::copysign(0.0, x);  // floor(-0.0) is -0.0
  return truncated > x ? truncated - 1.0 : truncated;
}

inline double frexpInline(double x, int* exponent) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  // Sign and exponent: 0 for zero and subnormals, 0x7ff for inf and NaN, >= 0x800 when negative.
  const auto biasedExponent = static_cast<int>(bits >> 52);
  if (biasedExponent == 0 || biasedExponent >= 0x7ff) return std::frexp(x, exponent);
  *exponent = biasedExponent - 1022;
  return std::bit_cast<double>((bits & 0x000fffffffffffffULL) | (std::uint64_t{1022} << 52));
}

}  // namespace lrsvo
