// TexelTiles' four-point path (sim/cpu_features.h): every operation the
// scalar sample() makes, in its order, four points at a time.
#include "lrsvo/sim/cpu_features.h"
#include "lrsvo/sim/texel_tiles.h"

namespace lrsvo {

bool TexelTiles::simd() { return cpuHasAvx2(); }

#ifdef LRSVO_AVX2

namespace {

// bilinearOf() for four points.
LRSVO_AVX2 __m256d bilinearOfFour(__m256d a, __m256d b, __m128 t00, __m128 t10, __m128 t01, __m128 t11) {
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d oneMinusA = _mm256_sub_pd(one, a), oneMinusB = _mm256_sub_pd(one, b);
  const __m256d top =
      _mm256_add_pd(_mm256_mul_pd(oneMinusA, _mm256_cvtps_pd(t00)), _mm256_mul_pd(a, _mm256_cvtps_pd(t10)));
  const __m256d bottom =
      _mm256_add_pd(_mm256_mul_pd(oneMinusA, _mm256_cvtps_pd(t01)), _mm256_mul_pd(a, _mm256_cvtps_pd(t11)));
  return _mm256_add_pd(_mm256_mul_pd(oneMinusB, top), _mm256_mul_pd(b, bottom));
}

}  // namespace

// Four points located: their blend fractions between the two levels, bilinear weights, and the first of each
// one's four texel pairs (t00; t10 beside it, t01 and t11 a tile row below).
struct TexelTiles::FourTexels {
  __m256d fraction, a, b;
  const TexelPair* texels[4];
};

LRSVO_AVX2 bool TexelTiles::locateFourAvx2(const double* x, const double* y, const float* footprints_m,
                                           FourTexels& found) const {
  // levels() for four footprints: the level from the exponent (all four the same, from 0 to kLevels - 2,
  // where levels() needs none of its special cases), the blend fraction from the mantissa.
  const __m256d scaled = _mm256_mul_pd(_mm256_cvtps_pd(_mm_loadu_ps(footprints_m)), _mm256_set1_pd(inverseTexel_[0]));
  const __m256i bits = _mm256_castpd_si256(scaled);
  const __m256i biasedExponent = _mm256_srli_epi64(bits, 52);  // with the sign bit above it
  const long long firstExponent = _mm256_extract_epi64(biasedExponent, 0);
  if (firstExponent < 1023 || firstExponent > 1023 + kLevels - 2) return false;
  const __m256i sameLevel = _mm256_cmpeq_epi64(biasedExponent, _mm256_set1_epi64x(firstExponent));
  if (_mm256_movemask_pd(_mm256_castsi256_pd(sameLevel)) != 0xF) return false;
  const int level = static_cast<int>(firstExponent - 1023);
  const __m256d mantissa = _mm256_castsi256_pd(_mm256_or_si256(
      _mm256_and_si256(bits, _mm256_set1_epi64x(0x000fffffffffffffLL)), _mm256_set1_epi64x(1022LL << 52)));
  found.fraction = _mm256_sub_pd(_mm256_mul_pd(_mm256_set1_pd(2.0), mantissa), _mm256_set1_pd(1.0));

  const LevelGrid& grid = grids_[level];
  constexpr std::int64_t kInt32Safe = std::int64_t{1} << 30;
  if (grid.width == 0 || std::abs(grid.tx0) > kInt32Safe || std::abs(grid.ty0) > kInt32Safe) return false;
  const __m256d inverse = _mm256_set1_pd(inverseTexel_[level]);
  const __m256d gx = _mm256_mul_pd(_mm256_loadu_pd(x), inverse), gy = _mm256_mul_pd(_mm256_loadu_pd(y), inverse);
  const __m256d fx = _mm256_floor_pd(gx), fy = _mm256_floor_pd(gy);
  // Texel indices as 32-bit integers, exact within +-2^30 texels (10^4 km at 1 cm); NaN fails the test too.
  const __m256d high = _mm256_set1_pd(0x1.0p30), low = _mm256_set1_pd(-0x1.0p30);
  const __m256d inRange =
      _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(fx, high, _CMP_LT_OQ), _mm256_cmp_pd(fx, low, _CMP_GT_OQ)),
                    _mm256_and_pd(_mm256_cmp_pd(fy, high, _CMP_LT_OQ), _mm256_cmp_pd(fy, low, _CMP_GT_OQ)));
  if (_mm256_movemask_pd(inRange) != 0xF) return false;
  const __m128i ix = _mm256_cvttpd_epi32(fx), iy = _mm256_cvttpd_epi32(fy);
  const __m128i tx = _mm_srai_epi32(ix, kTileBits), ty = _mm_srai_epi32(iy, kTileBits);
  const __m128i column = _mm_sub_epi32(tx, _mm_set1_epi32(static_cast<int>(grid.tx0)));
  const __m128i row = _mm_sub_epi32(ty, _mm_set1_epi32(static_cast<int>(grid.ty0)));
  const __m128i minusOne = _mm_set1_epi32(-1);
  const __m128i inGrid =
      _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi32(column, minusOne),
                                  _mm_cmplt_epi32(column, _mm_set1_epi32(static_cast<int>(grid.width)))),
                    _mm_and_si128(_mm_cmpgt_epi32(row, minusOne),
                                  _mm_cmplt_epi32(row, _mm_set1_epi32(static_cast<int>(grid.height)))));
  if (_mm_movemask_ps(_mm_castsi128_ps(inGrid)) != 0xF) return false;
  alignas(16) int slot[4], offset[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(slot),
                  _mm_add_epi32(_mm_mullo_epi32(row, _mm_set1_epi32(static_cast<int>(grid.width))), column));
  const __m128i u = _mm_sub_epi32(ix, _mm_slli_epi32(tx, kTileBits)),
                v = _mm_sub_epi32(iy, _mm_slli_epi32(ty, kTileBits));
  _mm_store_si128(reinterpret_cast<__m128i*>(offset), _mm_add_epi32(_mm_mullo_epi32(u, _mm_set1_epi32(layout_.xStep)),
                                                                    _mm_mullo_epi32(v, _mm_set1_epi32(layout_.yStep))));
  for (int i = 0; i < 4; ++i) {
    const TexelPair* tile = grid.texels[slot[i]];
    if (tile == nullptr) return false;
    found.texels[i] = tile + offset[i];
  }
  found.a = _mm256_sub_pd(gx, fx), found.b = _mm256_sub_pd(gy, fy);
  return true;
}

namespace {

// Four located points blended into their four samples from the two rows of
// pairs each one reads (t00 and the pair after it, and the two a tile row
// of memory on): [t00 t10] and [t01 t11] in tiles laid out along x,
// [t00 t01] and [t10 t11] along y.
LRSVO_AVX2 void blendFour(const __m256d fraction, const __m256d a, const __m256d b, __m128 nearPairs[4],
                          __m128 farPairs[4], bool alongY, float* out) {
  _MM_TRANSPOSE4_PS(nearPairs[0], nearPairs[1], nearPairs[2], nearPairs[3]);  // t00 values, coarser; the next's
  _MM_TRANSPOSE4_PS(farPairs[0], farPairs[1], farPairs[2], farPairs[3]);      // the same a tile row on
  const __m128 t10 = alongY ? farPairs[0] : nearPairs[2], t10Coarser = alongY ? farPairs[1] : nearPairs[3];
  const __m128 t01 = alongY ? nearPairs[2] : farPairs[0], t01Coarser = alongY ? nearPairs[3] : farPairs[1];
  const __m256d fine = bilinearOfFour(a, b, nearPairs[0], t10, t01, farPairs[2]);
  const __m256d coarse = bilinearOfFour(a, b, nearPairs[1], t10Coarser, t01Coarser, farPairs[3]);
  const __m256d blended =
      _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(1.0), fraction), fine), _mm256_mul_pd(fraction, coarse));
  _mm_storeu_ps(out, _mm256_cvtpd_ps(blended));
}

}  // namespace

LRSVO_AVX2 void TexelTiles::sampleManyAvx2(const double* x, const double* y, const float* footprints_m, int count,
                                           float* out) const {
  // Blocks of four located ahead of their blend: about as far as a pixel row's texel loads take to arrive
  // (measured with `lrsvo bench render`).
  constexpr int kAhead = 32;
  static_assert(sizeof(TexelPair) == 2 * sizeof(float), "two pairs are loaded as four floats");
  FourTexels ahead[kAhead];
  bool located[kAhead];
  const int blocks = count / 4;
  // Block k is located into slot k % kAhead on step k and blended from it on step k + kAhead, before that
  // step locates the next block into the same slot.
  for (int step = 0; step < blocks + kAhead; ++step) {
    const int slot = step % kAhead;
    if (step >= kAhead) {
      const int first = 4 * (step - kAhead);
      if (located[slot]) {
        // Per point, its pair t00 and the next in memory, and the two a tile row of memory on: [value,
        // coarser] x 2 each. The loads themselves are scalar: on AMD's cores a gather costs more than its loads.
        const FourTexels& four = ahead[slot];
        __m128 nearPairs[4], farPairs[4];
        for (int i = 0; i < 4; ++i) {
          nearPairs[i] = _mm_loadu_ps(&four.texels[i]->value);
          farPairs[i] = _mm_loadu_ps(&four.texels[i][kTile + 1].value);
        }
        blendFour(four.fraction, four.a, four.b, nearPairs, farPairs, alongY_, out + first);
      } else {
        for (int i = first; i < first + 4; ++i) out[i] = sample(x[i], y[i], footprints_m[i]);
      }
    }
    if (step < blocks) {
      const int first = 4 * step;
      located[slot] = locateFourAvx2(x + first, y + first, footprints_m + first, ahead[slot]);
      if (located[slot])
        for (const TexelPair* t : ahead[slot].texels) {
          _mm_prefetch(reinterpret_cast<const char*>(t), _MM_HINT_T0);
          _mm_prefetch(reinterpret_cast<const char*>(t + kTile + 1), _MM_HINT_T0);
        }
    }
  }
  for (int i = 4 * blocks; i < count; ++i) out[i] = sample(x[i], y[i], footprints_m[i]);
}

#else

void TexelTiles::sampleManyAvx2(const double* x, const double* y, const float* footprints_m, int count,
                                float* out) const {
  for (int i = 0; i < count; ++i) out[i] = sample(x[i], y[i], footprints_m[i]);
}

#endif

}  // namespace lrsvo
