#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

std::uint64_t splitmix64(std::uint64_t x) { return SplitMix64::at(x, 1); }

}  // namespace

std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
  return splitmix64(splitmix64(splitmix64(seed) ^ a) ^ b);
}

}  // namespace lrsvo
