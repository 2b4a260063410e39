#include "lrsvo/sim/value_noise.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/cpu_features.h"
#include "lrsvo/sim/inline_math.h"

namespace lrsvo {

namespace {

// Smooth value noise of unit wavelength in [-0.5, 0.5) at (x, y), its cell's corners kept in `cell`
// (fractalRowAvx2() makes the same operations four points at a time).
double valueNoise(double x, double y, std::uint32_t salt, LatticeCell& cell) {
  const std::int64_t ix = floorIndex(x), iy = floorIndex(y);
  cell.moveTo(ix, iy, salt);
  const double tx = x - static_cast<double>(ix), ty = y - static_cast<double>(iy);
  const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
  const double a = cell.a, b = cell.b, c = cell.c, d = cell.d;
  return a + (b - a) * sx + (c - a) * sy + (a - b - c + d) * sx * sy - 0.5;
}

// Calls term(inverse wavelength, weight times amplitude, noise salt, memo cell) for each octave fractal() sums,
// in its order (octaves faded out entirely are skipped), and returns what the sum is divided by.
template <typename Term>
double forEachTerm(const Octaves& octaves, double footprint, std::uint32_t salt, NoiseMemo& memo, Term&& term) {
  double amplitude = 1.0, total = 0.0;
  std::uint32_t octave = 0;
  // Wavelengths halve exactly, so their inverses double exactly: no division per octave.
  const double halfInverseFootprint = 0.5 / footprint;
  double inverseLambda = 1.0 / octaves.lambdaMax;
  for (double lambda = octaves.lambdaMax; lambda >= octaves.lambdaMin;
       lambda *= 0.5, inverseLambda *= 2.0, amplitude *= octaves.roughness, ++octave) {
    total += amplitude * amplitude;
    // How much of the octave survives averaging over the footprint: none at or below 2 footprints (the
    // sampling's Nyquist limit), all from 4 footprints up.
    const double weight = std::clamp(lambda * halfInverseFootprint - 1.0, 0.0, 1.0);
    if (weight > 0.0) term(inverseLambda, weight * amplitude, salt * 131u + octave, memo.cell(salt, octave));
  }
  return std::sqrt(total);
}

}  // namespace

FractalTerms fractalTerms(const Octaves& octaves, double footprint, std::uint32_t salt, NoiseMemo& memo) {
  FractalTerms sum;
  sum.norm = forEachTerm(
      octaves, footprint, salt, memo,
      [&](double inverseLambda, double weight, std::uint32_t noiseSalt, LatticeCell& cell) {
        if (sum.count == FractalTerms::kMaxTerms)
          throw Error("value noise: a fractal sums more than " + std::to_string(FractalTerms::kMaxTerms) + " octaves");
        sum.terms[sum.count++] = {inverseLambda, weight, noiseSalt, &cell};
      });
  return sum;
}

double fractal(double x, double y, const Octaves& octaves, double footprint, std::uint32_t salt, NoiseMemo& memo) {
  double sum = 0.0;
  const double norm = forEachTerm(octaves, footprint, salt, memo,
                                  [&](double inverseLambda, double weight, std::uint32_t noiseSalt, LatticeCell& cell) {
                                    sum += weight * valueNoise(x * inverseLambda, y * inverseLambda, noiseSalt, cell);
                                  });
  return sum / norm;
}

double fractalBound(const Octaves& octaves) {
  double amplitudes = 0.0, total = 0.0, amplitude = 1.0;
  for (double lambda = octaves.lambdaMax; lambda >= octaves.lambdaMin; lambda *= 0.5, amplitude *= octaves.roughness)
    amplitudes += amplitude, total += amplitude * amplitude;
  constexpr double kRounding = 1e-9;  // far above the few roundings of a fractal()'s sum
  return 0.5 * amplitudes / std::sqrt(total) * (1.0 + kRounding);
}

namespace {

double fractalOf(double x, double y, const FractalTerms& terms) {
  double sum = 0.0;
  for (int k = 0; k < terms.count; ++k) {
    const FractalTerms::Term& term = terms.terms[k];
    sum += term.weight * valueNoise(x * term.inverseLambda, y * term.inverseLambda, term.salt, *term.cell);
  }
  return sum / terms.norm;
}

}  // namespace

void fractalRow(const double* x, double y, int count, const Octaves& octaves, double footprint, std::uint32_t salt,
                NoiseMemo& memo, double* out) {
  const FractalTerms terms = fractalTerms(octaves, footprint, salt, memo);
  int done = 0;
#ifdef LRSVO_AVX2
  if (cpuHasAvx2()) fractalRowAvx2(x, y, count, terms, out), done = count - count % 4;
#endif
  for (int n = done; n < count; ++n) out[n] = fractalOf(x[n], y, terms);
}

}  // namespace lrsvo
