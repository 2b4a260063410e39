#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/sim/inline_math.h"

namespace lrsvo {

// A part of the ground an image will sample: a box in world x, y and the
// range of the pixel footprints there.
struct TexelRegion {
  Eigen::AlignedBox2d box;
  float minFootprint_m = 0.0f, maxFootprint_m = 0.0f;
};

// A lazily filled, world-aligned mipmap of a costly 2D texture
// f(x, y, footprint_m): level L holds f at texels spaced s_L = base * 2^L,
// each filtered over s_L, in square tiles computed on first use and kept
// while recent images use them, so each texel is computed once for many
// frames of a slowly moving camera. A pixel of footprint w reads the levels
// L and L + 1 with s_L <= w < 2 s_L, bilinearly in each and blended linearly
// in w between them (tri-linear filtering). Each texel of level L also holds
// level L + 1's bilinear interpolation at its position: that function is
// bilinear on level L's finer cells too, so one lookup in level L reads both
// levels. Values depend only on the texture and the position, never on what
// is cached: the same input gives the same image, and a texel whose tile the
// last require() did not list is computed on the spot, to the same value.
// require() also lays the tiles of the current image out in a small grid per
// level, so that sample() finds its tile by indexing (no hashing, no locks)
// on any number of threads.
class TexelTiles {
 public:
  using Function = std::function<float(double x, double y, double footprint_m)>;
  // The function along a row of a level's nodes: f((ix + n) s, iy s, s) into out[n] for n = 0 .. count - 1,
  // the node coordinates computed as static_cast<double>(ix + n) * s and static_cast<double>(iy) * s. A
  // texture may evaluate a row faster than point by point.
  using RowFunction = std::function<void(std::int64_t ix, std::int64_t iy, double texel_m, int count, float* out)>;

  // Throws lrsvo::Error on a non-positive base texel or keepImages < 1.
  TexelTiles(Function function, double baseTexel_m, int keepImages = 8);
  TexelTiles(RowFunction function, double baseTexel_m, int keepImages = 8);

  // Fills every tile that samples inside the regions will read, in parallel
  // when threads > 1 (graph/parallel_for.h; `function` is called from every
  // thread); tiles no image has read for keepImages calls are dropped. Not
  // safe while another thread samples. rowDirection is the world direction
  // (x, y) in which the image's rows run: the tiles are laid out so that
  // texels along the nearer world axis are neighbours in memory, so that a
  // row of pixels reads along cache lines whatever the camera's heading
  // (the layout switches past about 50 degrees, not at 45, so that a heading
  // near the diagonal does not switch it back and forth). Values do not
  // depend on the layout.
  void require(const std::vector<TexelRegion>& regions, int threads,
               const Eigen::Vector2d& rowDirection = Eigen::Vector2d::UnitX());
  // The texture at (x, y) for a pixel footprint. Safe on many threads at once.
  float sample(double x, double y, double footprint_m) const;
  // sample() at `count` points into out[0 ..], the same values bit for bit:
  // four points at a time with AVX2 where the CPU has it (simd()).
  void sampleMany(const double* x, const double* y, const float* footprints_m, int count, float* out) const;
  // Whether sampleMany() runs its AVX2 path on this CPU.
  static bool simd();
  // Whether the tiles the last require() listed lie with texels along y side by side (else along x).
  bool tilesAlongY() const { return alongY_; }

 private:
  static constexpr int kLevels = 32;  // up to 2^31 base texels: far coarser than any footprint
  static constexpr int kTileBits = 6;
  static constexpr int kTile = 1 << kTileBits;  // texels per side (+ one shared row and column for interpolation)
  // f at a node of a level, and the next level's bilinear interpolation there.
  struct TexelPair {
    float value, coarser;
  };
  struct Key {
    std::int64_t tx, ty;
    int level;
    bool operator==(const Key& other) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  struct Tile {
    std::vector<TexelPair> texels;  // (kTile + 1)^2, rows along x one after another, or columns if alongY
    std::int64_t lastUsed = 0;
    bool alongY = false;
  };
  // Where in a tile's texels node (u, v) of the tile lies: steps of one node along x and along y.
  struct Layout {
    int xStep = 1, yStep = kTile + 1;
    int at(std::int64_t u, std::int64_t v) const { return static_cast<int>(u * xStep + v * yStep); }
  };
  static Layout layoutOf(bool alongY) { return alongY ? Layout{kTile + 1, 1} : Layout{1, kTile + 1}; }
  // The texels of the tiles of one level that the last require() listed,
  // over the bounding box of their indices (null where none was listed).
  struct LevelGrid {
    std::int64_t tx0 = 0, ty0 = 0;
    std::int64_t width = 0, height = 0;
    std::vector<const TexelPair*> texels;
  };
  // The tiles of one level that one region covers, inclusive.
  struct TileRange {
    std::int64_t tx0, ty0, tx1, ty1;
    int level;
  };

  void levels(double footprint_m, int& level, double& fraction) const;
  std::int64_t texelIndex(double coordinate, int level) const;
  float texel(std::int64_t ix, std::int64_t iy, int level) const;  // f at a lattice point, uncached
  // The pair at a lattice point, uncached; `coarser` from the next level's nodes (c00 c10 c01 c11
  // around it: only those its position needs are read), as fill() computes it.
  TexelPair texelPair(std::int64_t ix, std::int64_t iy, int level) const;
  void fill(Tile& tile, const Key& key) const;  // a new tile's pairs, in the current layout
  static void transpose(Tile& tile);            // to the other layout
  std::vector<TileRange> tileRanges(const std::vector<TexelRegion>& regions) const;
  void layOut(const std::vector<TileRange>& ranges);
  // sampleMany() with AVX2 (sim/texel_tiles_avx2.cpp): sample()'s operations in the same order, four points at
  // a time. Each four are located (level, weights, texels) some blocks before they are blended, and their
  // texels requested from memory meanwhile: the lookup's time is otherwise spent waiting on those loads.
  void sampleManyAvx2(const double* x, const double* y, const float* footprints_m, int count, float* out) const;
  struct FourTexels;  // four located points (sim/texel_tiles_avx2.cpp)
  // Locates four points; false where one needs what only sample() does: the four at different levels, a tile
  // the grids do not hold, a footprint below the base texel.
  bool locateFourAvx2(const double* x, const double* y, const float* footprints_m, FourTexels& found) const;

  RowFunction function_;
  double base_m_;
  double texel_[kLevels];         // spacing per level
  double inverseTexel_[kLevels];  // 1 / spacing: texel indices use this alone, wherever computed
  int keep_;
  std::int64_t images_ = 0;  // require() calls
  std::unordered_map<Key, std::unique_ptr<Tile>, KeyHash> tiles_;
  std::array<LevelGrid, kLevels> grids_;
  bool alongY_ = false;  // the layout of every tile the grids list
  Layout layout_;        // layoutOf(alongY_)
};

// The per-pixel path, inline: the renderer calls sample() for every ground pixel.

inline void TexelTiles::levels(double footprint_m, int& level, double& fraction) const {
  // footprint = m 2^e base with m in [0.5, 1): level e - 1 (texel s <= footprint < 2 s), blended towards the
  // next level linearly in the footprint (exact powers of two, no logarithm per pixel).
  int exponent;
  const double mantissa = frexpInline(footprint_m * inverseTexel_[0], &exponent);
  level = exponent - 1, fraction = 2.0 * mantissa - 1.0;
  if (level < 0 || !(mantissa > 0.0)) level = 0, fraction = 0.0;  // finer than the base texel: the base level
  if (level > kLevels - 2 || std::isinf(mantissa)) level = kLevels - 2, fraction = 0.0;
}

inline std::int64_t TexelTiles::texelIndex(double coordinate, int level) const {
  return floorIndex(coordinate * inverseTexel_[level]);
}

// (1 - b) ((1 - a) t00 + a t10) + b ((1 - a) t01 + a t11): every bilinear interpolation of this class, in
// this order of operations (sim/texel_tiles_avx2.cpp repeats it four at a time; code that includes this
// header and compares the two compiles with -ffp-contract=off, as sim/CMakeLists.txt explains).
inline double bilinearOf(double a, double b, double t00, double t10, double t01, double t11) {
  return (1.0 - b) * ((1.0 - a) * t00 + a * t10) + b * ((1.0 - a) * t01 + a * t11);
}

inline float TexelTiles::sample(double x, double y, double footprint_m) const {
  int level;
  double fraction;
  levels(footprint_m, level, fraction);
  const double gx = x * inverseTexel_[level], gy = y * inverseTexel_[level];
  const std::int64_t ix = floorIndex(gx), iy = floorIndex(gy);
  // Texel indices first, then tiles (>> is floor division, also below zero), so
  // that the texel and its right and lower neighbours lie in one tile.
  const std::int64_t tx = ix >> kTileBits, ty = iy >> kTileBits;
  const LevelGrid& grid = grids_[level];
  const std::int64_t column = tx - grid.tx0, row = ty - grid.ty0;
  const TexelPair* texels = column >= 0 && column < grid.width && row >= 0 && row < grid.height
                                ? grid.texels[row * grid.width + column]
                                : nullptr;
  TexelPair t00, t10, t01, t11;
  if (texels != nullptr) [[likely]] {
    const TexelPair* t = texels + layout_.at(ix - (tx << kTileBits), iy - (ty << kTileBits));
    t00 = t[0], t10 = t[layout_.xStep], t01 = t[layout_.yStep], t11 = t[layout_.xStep + layout_.yStep];
  } else {
    t00 = texelPair(ix, iy, level), t10 = texelPair(ix + 1, iy, level);
    t01 = texelPair(ix, iy + 1, level), t11 = texelPair(ix + 1, iy + 1, level);
  }
  const double a = gx - static_cast<double>(ix), b = gy - static_cast<double>(iy);
  const double fine = bilinearOf(a, b, t00.value, t10.value, t01.value, t11.value);
  const double coarse = bilinearOf(a, b, t00.coarser, t10.coarser, t01.coarser, t11.coarser);
  return static_cast<float>((1.0 - fraction) * fine + fraction * coarse);
}

}  // namespace lrsvo
