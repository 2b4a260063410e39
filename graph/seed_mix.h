#pragma once

#include <cstdint>

namespace lrsvo {

// splitmix64's output function: a bijective, well-mixed hash of 64 bits.
inline std::uint64_t splitMix64Finalise(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A well-mixed 64-bit seed from a seed and two labels (e.g. a purpose and an
// index, or a terrain cell's indices), so that each part of a computation
// draws from its own reproducible stream (splitmix64 finaliser). The one rule
// by which lrsvo derives streams from a user's seed: unlike seed + k, whose
// stream k + 1 is the next seed's stream k, neighbouring seeds share nothing.
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0);

// A small, fast generator (splitmix64) for the many short streams of a
// procedural world, one per terrain cell and looked up again on every height
// query, where seeding a Mersenne twister each time would cost microseconds.
// A UniformRandomBitGenerator, for the <random> distributions.
class SplitMix64 {
 public:
  static constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;
  using result_type = std::uint64_t;
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  result_type operator()() { return splitMix64Finalise(state_ += kGolden); }
  // The n-th output (n >= 1) of the generator seeded with `seed`, without running it.
  static result_type at(std::uint64_t seed, std::uint64_t n) { return splitMix64Finalise(seed + n * kGolden); }

 private:
  std::uint64_t state_;
};

}  // namespace lrsvo
