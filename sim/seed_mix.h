#pragma once

#include <cstdint>

namespace lrsvo {

// A well-mixed 64-bit seed from a seed and two labels (e.g. a terrain cell's
// indices, or a camera index and a purpose), so that each part of a
// simulation draws from its own reproducible stream (splitmix64 finaliser).
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0);

}  // namespace lrsvo
