#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace lrsvo {

// A lazily filled, world-aligned mipmap of a costly 2D texture
// f(x, y, footprint_m): level L holds f at texels spaced s_L = base * 2^L,
// each filtered over s_L, in square tiles computed on first use and kept
// while recent images use them. A pixel of footprint w reads the levels L
// and L + 1 with s_L <= w < 2 s_L, bilinearly in each and blended linearly in
// w between them (tri-linear filtering), so each texel is
// computed once for many frames of a slowly moving camera. Values depend only
// on the texture and the position, never on what is cached: the same input
// gives the same image. require() also lays the tiles of the current image
// out in a small grid per level, so that sample() finds its tile by indexing
// (no hashing, no locks) on any number of threads.
class TexelTiles {
 public:
  using Function = std::function<float(double x, double y, double footprint_m)>;

  // Throws lrsvo::Error on a non-positive base texel or keepImages < 1.
  TexelTiles(Function function, double baseTexel_m, int keepImages = 8);

  // Point i of `count` to be sampled: fills its (x, y) and footprint and
  // returns true, or returns false when it will not be sampled. Called from
  // up to `threads` threads at once.
  using PointSource = std::function<bool(std::size_t i, Eigen::Vector2d& xy, float& footprint_m)>;

  // Fills every tile that sample() will read for the `count` points that
  // `point` gives, on up to `threads` threads; tiles no image has read for
  // keepImages calls are dropped. Not safe while another thread samples.
  void require(std::size_t count, const PointSource& point, int threads);
  // The texture at (x, y) for a pixel footprint; (x, y, footprint) must have
  // been passed to the last require(). Safe on many threads at once.
  float sample(double x, double y, double footprint_m) const;

 private:
  static constexpr int kLevels = 32;  // up to 2^31 base texels: far coarser than any footprint
  static constexpr int kTile = 64;    // texels per side (+ one shared row and column for interpolation)
  struct Key {
    std::int64_t tx, ty;
    int level;
    bool operator==(const Key& other) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  struct Tile {
    std::vector<float> texels;  // (kTile + 1)^2, row-major in y
    std::int64_t lastUsed = 0;
  };
  // The tiles of one level that the last require() listed, over the bounding
  // box of their indices (null where none was listed).
  struct LevelGrid {
    std::int64_t tx0 = 0, ty0 = 0;
    std::int64_t width = 0, height = 0;
    std::vector<const Tile*> tiles;
  };

  void levels(double footprint_m, int& level, double& fraction) const;
  std::int64_t texelIndex(double coordinate, int level) const;
  Key keyOf(double x, double y, int level) const;
  std::vector<Key> listKeys(std::size_t count, const PointSource& point, int threads) const;
  void layOut(const std::vector<Key>& keys);
  float bilinear(double x, double y, int level) const;

  Function function_;
  double base_m_;
  double texel_[kLevels];         // spacing per level
  double inverseTexel_[kLevels];  // 1 / spacing: texel indices use this alone, wherever computed
  int keep_;
  std::int64_t images_ = 0;  // require() calls
  std::unordered_map<Key, std::unique_ptr<Tile>, KeyHash> tiles_;
  std::array<LevelGrid, kLevels> grids_;
};

}  // namespace lrsvo
