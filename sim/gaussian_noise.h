#pragma once

#include <cstdint>

namespace lrsvo {

// Seeded Gaussian noise at the cost of a table lookup, for a sensor's every
// pixel. Draw n of a key is quantile k of the standard normal, k being 16
// bits of output n / 4 of the key's SplitMix64 stream (one hash, four draws).
// The 2^16 quantiles (at the midpoints of equal probabilities, out to 4.3
// sigma) are scaled to a variance of exactly 1 and are symmetric, so the
// draws have mean 0 and variance 1. A draw depends on the key and its index
// alone: not on the threads, nor on which draws were made before.
float standardNormalDraw(std::uint64_t key, std::uint64_t index);

// values[i] += sigma * standardNormalDraw(key, first + i) for i < count.
void addGaussianNoise(float* values, int count, double sigma, std::uint64_t key, std::uint64_t first);

}  // namespace lrsvo
