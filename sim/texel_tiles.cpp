#include "sim/texel_tiles.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <string>
#include <utility>

#include "graph/error.h"
#include "graph/parallel_for.h"

namespace lrsvo {
namespace {}  // namespace

std::size_t TexelTiles::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = static_cast<std::uint64_t>(k.tx) * 0x9e3779b97f4a7c15ULL;
  h ^= static_cast<std::uint64_t>(k.ty) * 0xc2b2ae3d27d4eb4fULL + static_cast<std::uint64_t>(k.level);
  return static_cast<std::size_t>(h ^ (h >> 29));
}

TexelTiles::TexelTiles(Function function, double baseTexel_m, int keepImages)
    : function_(std::move(function)), base_m_(baseTexel_m), keep_(keepImages) {
  if (!(std::isfinite(baseTexel_m) && baseTexel_m > 0.0) || keepImages < 1)
    throw Error("texel tiles: the base texel must be finite and > 0 and keepImages >= 1");
  for (int level = 0; level < kLevels; ++level) texel_[level] = std::ldexp(base_m_, level);
}

double TexelTiles::texel(int level) const { return texel_[level]; }

void TexelTiles::levels(double footprint_m, int& level, double& fraction) const {
  const double l = std::clamp(std::log2(std::max(footprint_m, 1e-300) / base_m_), 0.0, kLevels - 2.0);
  level = static_cast<int>(l);
  fraction = l - level;
}

TexelTiles::Key TexelTiles::keyOf(double x, double y, int level) const {
  // Texel indices first, then tiles (an exact division of integers), so that
  // bilinear() finds the texel and its right and lower neighbours in the tile.
  const double s = texel(level);
  return {static_cast<std::int64_t>(std::floor(std::floor(x / s) / kTile)),
          static_cast<std::int64_t>(std::floor(std::floor(y / s) / kTile)), level};
}

void TexelTiles::require(const std::vector<Eigen::Vector2d>& points, const std::vector<float>& footprints_m,
                         int threads) {
  if (points.size() != footprints_m.size()) throw Error("texel tiles: one footprint per point needed");
  ++images_;
  // Unique over all instances: a thread's remembered tile (bilinear()) from
  // an earlier require() or another instance is never taken for current.
  static std::atomic<std::int64_t> calls{0};
  generation_ = ++calls;
  // Neighbouring pixels mostly share tiles (at one or two levels): skip keys among the last few listed.
  std::vector<Key> wanted;
  for (std::size_t i = 0; i < points.size(); ++i) {
    int level;
    double fraction;
    levels(footprints_m[i], level, fraction);
    for (int l = level; l <= level + (fraction > 0.0); ++l) {
      const Key key = keyOf(points[i].x(), points[i].y(), l);
      const auto recent = wanted.end() - std::min<std::ptrdiff_t>(4, static_cast<std::ptrdiff_t>(wanted.size()));
      if (std::find(recent, wanted.end(), key) == wanted.end()) wanted.push_back(key);
    }
  }
  std::vector<Tile*> missing;
  std::vector<Key> missingKeys;
  for (const Key& key : wanted) {
    auto found = tiles_.find(key);
    if (found == tiles_.end()) {
      found = tiles_.emplace(key, std::make_unique<Tile>()).first;
      missing.push_back(found->second.get());
      missingKeys.push_back(key);
    }
    found->second->lastUsed = images_;
  }
  parallelFor(0, static_cast<int>(missing.size()), threads, [&](int i) {
    const Key& key = missingKeys[i];
    const double s = texel(key.level);
    std::vector<float>& texels = missing[i]->texels;
    texels.resize((kTile + 1) * (kTile + 1));
    for (int v = 0; v <= kTile; ++v)
      for (int u = 0; u <= kTile; ++u)
        texels[v * (kTile + 1) + u] =
            function_(static_cast<double>(key.tx * kTile + u) * s, static_cast<double>(key.ty * kTile + v) * s, s);
  });
  std::erase_if(tiles_, [&](const auto& entry) { return entry.second->lastUsed <= images_ - keep_; });
}

float TexelTiles::bilinear(double x, double y, int level) const {
  const double s = texel(level);
  const double gx = x / s, gy = y / s;
  const double fx = std::floor(gx), fy = std::floor(gy);
  const Key key = keyOf(x, y, level);
  // Neighbouring pixels read the same tiles: each thread remembers its last
  // tile per level (valid until the next require()) and skips the map.
  struct Recent {
    std::int64_t generation = -1;
    Key key{};
    const Tile* tile = nullptr;
  };
  thread_local std::array<Recent, kLevels> recent;
  Recent& last = recent[level];
  if (last.generation != generation_ || !(last.key == key)) {
    const auto found = tiles_.find(key);
    if (found == tiles_.end()) throw Error("texel tiles: sample() outside the tiles of the last require()");
    last = {generation_, key, found->second.get()};
  }
  const int u = static_cast<int>(static_cast<std::int64_t>(fx) - key.tx * kTile);
  const int v = static_cast<int>(static_cast<std::int64_t>(fy) - key.ty * kTile);
  const float* t = &last.tile->texels[v * (kTile + 1) + u];
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
