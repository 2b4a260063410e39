// fractalRow() four points at a time: each point in a lane, every operation
// the scalar valueNoise() and fractal() make, in their order
// (sim/cpu_features.h).
#include <cstdint>

#include "lrsvo/sim/cpu_features.h"
#include "lrsvo/sim/inline_math.h"
#include "lrsvo/sim/value_noise.h"

namespace lrsvo {

#ifdef LRSVO_AVX2

namespace {

// tt (3 - 2 t): the noise's smooth step, as valueNoise() rounds it.
LRSVO_AVX2 __m256d smoothStep(__m256d t) {
  return _mm256_mul_pd(_mm256_mul_pd(t, t), _mm256_sub_pd(_mm256_set1_pd(3.0), _mm256_mul_pd(_mm256_set1_pd(2.0), t)));
}

}  // namespace

LRSVO_AVX2 void fractalRowAvx2(const double* x, double y, int count, const FractalTerms& terms, double* out) {
  // Per term, y's lattice row and smooth step: the same for every point of the row.
  std::int64_t rows[FractalTerms::kMaxTerms];
  double sy[FractalTerms::kMaxTerms];
  for (int k = 0; k < terms.count; ++k) {
    const double gy = y * terms.terms[k].inverseLambda;
    rows[k] = floorIndex(gy);
    const double ty = gy - static_cast<double>(rows[k]);
    sy[k] = ty * ty * (3.0 - 2.0 * ty);
  }
  const __m256d half = _mm256_set1_pd(0.5), norm = _mm256_set1_pd(terms.norm);
  for (int first = 0; first + 4 <= count; first += 4) {
    const __m256d px = _mm256_loadu_pd(x + first);
    __m256d sum = _mm256_setzero_pd();
    for (int k = 0; k < terms.count; ++k) {
      const FractalTerms::Term& term = terms.terms[k];
      const __m256d gx = _mm256_mul_pd(px, _mm256_set1_pd(term.inverseLambda));
      const __m256d fx = _mm256_floor_pd(gx);
      const __m256d sx = smoothStep(_mm256_sub_pd(gx, fx));
      // The corners of each point's lattice cell, from the memo while the points stay in its cell.
      alignas(32) double cellX[4], a[4], b[4], c[4], d[4];
      _mm256_store_pd(cellX, fx);
      LatticeCell& cell = *term.cell;
      for (int lane = 0; lane < 4; ++lane) {
        cell.moveTo(static_cast<std::int64_t>(cellX[lane]), rows[k], term.salt);
        a[lane] = cell.a, b[lane] = cell.b, c[lane] = cell.c, d[lane] = cell.d;
      }
      const __m256d ca = _mm256_load_pd(a), cb = _mm256_load_pd(b), cc = _mm256_load_pd(c), cd = _mm256_load_pd(d);
      const __m256d ySmooth = _mm256_set1_pd(sy[k]);
      // a + (b - a) sx + (c - a) sy + (a - b - c + d) sx sy - 0.5, left to right.
      __m256d noise = _mm256_add_pd(ca, _mm256_mul_pd(_mm256_sub_pd(cb, ca), sx));
      noise = _mm256_add_pd(noise, _mm256_mul_pd(_mm256_sub_pd(cc, ca), ySmooth));
      const __m256d twist = _mm256_add_pd(_mm256_sub_pd(_mm256_sub_pd(ca, cb), cc), cd);
      noise = _mm256_add_pd(noise, _mm256_mul_pd(_mm256_mul_pd(twist, sx), ySmooth));
      noise = _mm256_sub_pd(noise, half);
      sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(term.weight), noise));
    }
    _mm256_storeu_pd(out + first, _mm256_div_pd(sum, norm));
  }
}

#endif

}  // namespace lrsvo
