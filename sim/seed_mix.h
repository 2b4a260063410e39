#pragma once

#include <cstdint>

namespace lrsvo {

// A well-mixed 64-bit seed from a seed and two labels (e.g. a terrain cell's
// indices, or a camera index and a purpose), so that each part of a
// simulation draws from its own reproducible stream (splitmix64 finaliser).
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0);

// A small, fast generator (splitmix64) for the many short streams of a
// procedural world, one per terrain cell and looked up again on every height
// query, where seeding a Mersenne twister each time would cost microseconds.
// A UniformRandomBitGenerator, for the <random> distributions.
class SplitMix64 {
 public:
  using result_type = std::uint64_t;
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  result_type operator()();

 private:
  std::uint64_t state_;
};

}  // namespace lrsvo
