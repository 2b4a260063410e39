#pragma once

#include <array>
#include <cstdint>

namespace lrsvo {

// Seeded value noise and its octave sums, the grain of the ground texture
// (sim/ground_texture.h). Pure functions of their arguments; the memo only
// spares recomputing lattice hashes.

inline std::uint64_t mixBits(std::uint64_t h) {
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 29;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 32);
}

// A hash of a lattice point and a salt, uniform in [0, 1), in two steps:
// the row's part (y and the salt), then the point's.
inline std::uint64_t rowHash(std::int64_t y, std::uint32_t salt) {
  return mixBits(static_cast<std::uint64_t>(y) + (static_cast<std::uint64_t>(salt) << 40));
}
inline double pointHash01(std::int64_t x, std::uint64_t row) {
  return static_cast<double>(mixBits(static_cast<std::uint64_t>(x) * 0x9e3779b97f4a7c15ULL ^ row) >> 11) * 0x1.0p-53;
}
inline double hash01(std::int64_t x, std::int64_t y, std::uint32_t salt) { return pointHash01(x, rowHash(y, salt)); }

// The corner hashes of one lattice cell of one noise layer, as the noise last used them.
struct LatticeCell {
  bool filled = false;
  std::uint32_t salt = 0;
  std::int64_t ix = 0, iy = 0;
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;  // at (ix, iy), (ix + 1, iy), (ix, iy + 1), (ix + 1, iy + 1)

  // Holds cell (x, y) of layer `layer` from now on: its corners hashed unless it already does.
  void moveTo(std::int64_t x, std::int64_t y, std::uint32_t layer) {
    if (filled && ix == x && iy == y && salt == layer) return;
    const std::uint64_t row0 = rowHash(y, layer), row1 = rowHash(y + 1, layer);
    filled = true, salt = layer, ix = x, iy = y;
    a = pointHash01(x, row0), b = pointHash01(x + 1, row0);
    c = pointHash01(x, row1), d = pointHash01(x + 1, row1);
  }
};

// The last lattice cell of each noise layer and octave. A texture is
// evaluated along rows of texels a fraction of a lattice cell apart, so most
// octaves stay in one cell for many texels: their four corner hashes (six
// mixes) are looked up, not recomputed. One memo per thread.
struct NoiseMemo {
  static constexpr int kOctaveBits = 3, kLayerBits = 5;  // slots for 32 layers of 8 octaves
  std::array<LatticeCell, 1 << (kOctaveBits + kLayerBits)> cells;
  LatticeCell& cell(std::uint32_t salt, std::uint32_t octave) {
    return cells[((salt << kOctaveBits) + octave) & (cells.size() - 1)];
  }
};

// The octaves of a fractal(): wavelengths from lambdaMax down to lambdaMin
// (halving), each `roughness` times the amplitude of the one above.
struct Octaves {
  double lambdaMin, lambdaMax, roughness;
};

// The terms fractal() sums at one footprint, in its order (octaves fully
// faded out are left out): each one's inverse wavelength, weight times
// amplitude, noise salt and memo cell; and what the sum is divided by.
struct FractalTerms {
  static constexpr int kMaxTerms = 64;  // octaves a fractal may sum; the texture's sum at most 8
  struct Term {
    double inverseLambda, weight;
    std::uint32_t salt;
    LatticeCell* cell;
  };
  std::array<Term, kMaxTerms> terms;
  int count = 0;
  double norm = 1.0;
};
// Throws lrsvo::Error on more than kMaxTerms octaves.
FractalTerms fractalTerms(const Octaves& octaves, double footprint, std::uint32_t salt, NoiseMemo& memo);

// Octaves of value noise at (x, y), those finer than the footprint faded
// out (none at or below 2 footprints, all from 4 up: nothing aliases);
// scaled so that its spread is that of one octave (about +-0.5) however many
// octaves it sums.
double fractal(double x, double y, const Octaves& octaves, double footprint, std::uint32_t salt, NoiseMemo& memo);
// The largest |fractal()| at any point and footprint: each octave's noise
// lies in [-0.5, 0.5), its weight in [0, 1].
double fractalBound(const Octaves& octaves);
// fractal() at (x[n], y) for n = 0 .. count - 1 into out[0 ..], the same
// values bit for bit: four points at a time with AVX2 where the CPU has it
// (sim/cpu_features.h). Throws lrsvo::Error on more than
// FractalTerms::kMaxTerms octaves.
void fractalRow(const double* x, double y, int count, const Octaves& octaves, double footprint, std::uint32_t salt,
                NoiseMemo& memo, double* out);
// fractalRow()'s four-point path (sim/value_noise_avx2.cpp, x86-64 only),
// for the first count - count % 4 points; only where cpuHasAvx2().
void fractalRowAvx2(const double* x, double y, int count, const FractalTerms& terms, double* out);

}  // namespace lrsvo
