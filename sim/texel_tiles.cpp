#include "sim/texel_tiles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "graph/error.h"
#include "graph/parallel_for.h"
#include "sim/inline_math.h"

namespace lrsvo {
namespace {

// floor(i / kDivisor) for any sign of i.
template <std::int64_t kDivisor>
std::int64_t floorDivide(std::int64_t i) {
  return (i >= 0 ? i : i - (kDivisor - 1)) / kDivisor;
}

}  // namespace

std::size_t TexelTiles::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = static_cast<std::uint64_t>(k.tx) * 0x9e3779b97f4a7c15ULL;
  h ^= static_cast<std::uint64_t>(k.ty) * 0xc2b2ae3d27d4eb4fULL + static_cast<std::uint64_t>(k.level);
  return static_cast<std::size_t>(h ^ (h >> 29));
}

TexelTiles::TexelTiles(Function function, double baseTexel_m, int keepImages)
    : function_(std::move(function)), base_m_(baseTexel_m), keep_(keepImages) {
  if (!(std::isfinite(baseTexel_m) && baseTexel_m > 0.0) || keepImages < 1)
    throw Error("texel tiles: the base texel must be finite and > 0 and keepImages >= 1");
  for (int level = 0; level < kLevels; ++level) {
    texel_[level] = std::ldexp(base_m_, level);
    inverseTexel_[level] = 1.0 / texel_[level];
  }
}

inline void TexelTiles::levels(double footprint_m, int& level, double& fraction) const {
  // footprint = m 2^e base with m in [0.5, 1): level e - 1 (texel s <= footprint < 2 s), blended towards the
  // next level linearly in the footprint (exact powers of two, no logarithm per pixel).
  int exponent;
  const double mantissa = frexpInline(footprint_m / base_m_, &exponent);
  level = exponent - 1, fraction = 2.0 * mantissa - 1.0;
  if (level < 0 || !(mantissa > 0.0)) level = 0, fraction = 0.0;  // finer than the base texel: the base level
  if (level > kLevels - 2 || std::isinf(mantissa)) level = kLevels - 2, fraction = 0.0;
}

inline std::int64_t TexelTiles::texelIndex(double coordinate, int level) const {
  return static_cast<std::int64_t>(floorInline(coordinate * inverseTexel_[level]));
}

inline TexelTiles::Key TexelTiles::keyOf(double x, double y, int level) const {
  // Texel indices first, then tiles (an exact division of integers), so that
  // bilinear() finds the texel and its right and lower neighbours in the tile.
  return {floorDivide<kTile>(texelIndex(x, level)), floorDivide<kTile>(texelIndex(y, level)), level};
}

std::vector<TexelTiles::Key> TexelTiles::listKeys(std::size_t count, const PointSource& point, int threads) const {
  // Blocks of points in parallel; within a block, neighbouring pixels mostly
  // share tiles (at one or two levels): skip a key equal to the last one
  // listed at its level.
  constexpr int kBlock = 4096;
  const int blocks = static_cast<int>((count + kBlock - 1) / kBlock);
  std::vector<std::vector<Key>> perBlock(blocks);
  auto byLevelAndPosition = [](const Key& a, const Key& b) {
    return std::tie(a.level, a.ty, a.tx) < std::tie(b.level, b.ty, b.tx);
  };
  parallelFor(0, blocks, threads, 1, [&](int b) {
    std::vector<Key>& wanted = perBlock[b];
    std::array<Key, kLevels> lastListed;
    lastListed.fill(Key{0, 0, -1});
    const std::size_t end = std::min(count, static_cast<std::size_t>(b + 1) * kBlock);
    Eigen::Vector2d xy;
    float footprint;
    for (std::size_t i = static_cast<std::size_t>(b) * kBlock; i < end; ++i) {
      if (!point(i, xy, footprint)) continue;
      int level;
      double fraction;
      levels(footprint, level, fraction);
      for (int l = level; l <= level + (fraction > 0.0); ++l) {
        const Key key = keyOf(xy.x(), xy.y(), l);
        if (key == lastListed[l]) continue;
        wanted.push_back(key);
        lastListed[l] = key;
      }
    }
    std::sort(wanted.begin(), wanted.end(), byLevelAndPosition);
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  });
  std::vector<Key> keys;
  for (const std::vector<Key>& block : perBlock) keys.insert(keys.end(), block.begin(), block.end());
  std::sort(keys.begin(), keys.end(), byLevelAndPosition);
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

void TexelTiles::require(std::size_t count, const PointSource& point, int threads) {
  ++images_;
  const std::vector<Key> keys = listKeys(count, point, threads);
  std::vector<Tile*> missing;
  std::vector<Key> missingKeys;
  for (const Key& key : keys) {
    auto found = tiles_.find(key);
    if (found == tiles_.end()) {
      found = tiles_.emplace(key, std::make_unique<Tile>()).first;
      missing.push_back(found->second.get());
      missingKeys.push_back(key);
    }
    found->second->lastUsed = images_;
  }
  parallelFor(0, static_cast<int>(missing.size()), threads, 1, [&](int i) {
    const Key& key = missingKeys[i];
    const double s = texel_[key.level];
    std::vector<float>& texels = missing[i]->texels;
    texels.resize((kTile + 1) * (kTile + 1));
    for (int v = 0; v <= kTile; ++v)
      for (int u = 0; u <= kTile; ++u)
        texels[v * (kTile + 1) + u] =
            function_(static_cast<double>(key.tx * kTile + u) * s, static_cast<double>(key.ty * kTile + v) * s, s);
  });
  std::erase_if(tiles_, [&](const auto& entry) { return entry.second->lastUsed <= images_ - keep_; });
  layOut(keys);
}

void TexelTiles::layOut(const std::vector<Key>& keys) {
  for (LevelGrid& grid : grids_) grid = LevelGrid{};
  // keys are sorted by level: each level's keys form one run.
  for (auto first = keys.begin(); first != keys.end();) {
    const int level = first->level;
    const auto last = std::find_if(first, keys.end(), [&](const Key& k) { return k.level != level; });
    LevelGrid& grid = grids_[level];
    std::int64_t tx1 = first->tx, ty1 = first->ty;
    grid.tx0 = first->tx, grid.ty0 = first->ty;
    for (auto k = first; k != last; ++k) {
      grid.tx0 = std::min(grid.tx0, k->tx), tx1 = std::max(tx1, k->tx);
      grid.ty0 = std::min(grid.ty0, k->ty), ty1 = std::max(ty1, k->ty);
    }
    grid.width = tx1 - grid.tx0 + 1, grid.height = ty1 - grid.ty0 + 1;
    grid.tiles.assign(static_cast<std::size_t>(grid.width * grid.height), nullptr);
    for (auto k = first; k != last; ++k)
      grid.tiles[(k->ty - grid.ty0) * grid.width + (k->tx - grid.tx0)] = tiles_.at(*k).get();
    first = last;
  }
}

inline float TexelTiles::bilinear(double x, double y, int level) const {
  const double gx = x * inverseTexel_[level], gy = y * inverseTexel_[level];
  const double fx = floorInline(gx), fy = floorInline(gy);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const std::int64_t tx = floorDivide<kTile>(ix), ty = floorDivide<kTile>(iy);
  const LevelGrid& grid = grids_[level];
  const std::int64_t column = tx - grid.tx0, row = ty - grid.ty0;
  const Tile* tile = column >= 0 && column < grid.width && row >= 0 && row < grid.height
                         ? grid.tiles[row * grid.width + column]
                         : nullptr;
  if (tile == nullptr) throw Error("texel tiles: sample() outside the tiles of the last require()");
  const int u = static_cast<int>(ix - tx * kTile), v = static_cast<int>(iy - ty * kTile);
  const float* t = &tile->texels[v * (kTile + 1) + u];
  const double a = gx - fx, b = gy - fy;
  return static_cast<float>((1.0 - b) * ((1.0 - a) * t[0] + a * t[1]) +
                            b * ((1.0 - a) * t[kTile + 1] + a * t[kTile + 2]));
}

float TexelTiles::sample(double x, double y, double footprint_m) const {
  int level;
  double fraction;
  levels(footprint_m, level, fraction);
  const float fine = bilinear(x, y, level);
  return fraction > 0.0 ? static_cast<float>((1.0 - fraction) * fine + fraction * bilinear(x, y, level + 1)) : fine;
}

}  // namespace lrsvo
