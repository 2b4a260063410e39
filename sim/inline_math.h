#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace lrsvo {

// std::frexp without a call into libm, bit for bit the same result, and
// floor as an integer without one (g++ calls libm for std::floor unless the
// target has SSE4.1): the renderer runs them several times per pixel.
inline double frexpInline(double x, int* exponent) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  // Sign and exponent: 0 for zero and subnormals, 0x7ff for inf and NaN, >= 0x800 when negative.
  const auto biasedExponent = static_cast<int>(bits >> 52);
  if (biasedExponent == 0 || biasedExponent >= 0x7ff) return std::frexp(x, exponent);
  *exponent = biasedExponent - 1022;
  return std::bit_cast<double>((bits & 0x000fffffffffffffULL) | (std::uint64_t{1022} << 52));
}

// floor(x) as an integer, for finite |x| < 2^62 (texel and lattice
// indices): the truncation, one lower where it rounded up; no branch.
inline std::int64_t floorIndex(double x) {
  const auto truncated = static_cast<std::int64_t>(x);
  return truncated - static_cast<std::int64_t>(x < static_cast<double>(truncated));
}

}  // namespace lrsvo
