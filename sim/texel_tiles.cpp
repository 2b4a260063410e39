#include "lrsvo/sim/texel_tiles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"

namespace lrsvo {
std::size_t TexelTiles::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = static_cast<std::uint64_t>(k.tx) * 0x9e3779b97f4a7c15ULL;
  h ^= static_cast<std::uint64_t>(k.ty) * 0xc2b2ae3d27d4eb4fULL + static_cast<std::uint64_t>(k.level);
  return static_cast<std::size_t>(h ^ (h >> 29));
}

TexelTiles::TexelTiles(Function function, double baseTexel_m, int keepImages)
    : TexelTiles(
          [point = std::move(function)](std::int64_t ix, std::int64_t iy, double s, int count, float* out) {
            for (int n = 0; n < count; ++n)
              out[n] = point(static_cast<double>(ix + n) * s, static_cast<double>(iy) * s, s);
          },
          baseTexel_m, keepImages) {}

TexelTiles::TexelTiles(RowFunction function, double baseTexel_m, int keepImages)
    : function_(std::move(function)), base_m_(baseTexel_m), keep_(keepImages) {
  if (!(std::isfinite(baseTexel_m) && baseTexel_m > 0.0) || keepImages < 1)
    throw Error("texel tiles: the base texel must be finite and > 0 and keepImages >= 1");
  for (int level = 0; level < kLevels; ++level) {
    texel_[level] = std::ldexp(base_m_, level);
    inverseTexel_[level] = 1.0 / texel_[level];
  }
}

void TexelTiles::sampleMany(const double* x, const double* y, const float* footprints_m, int count, float* out) const {
  if (simd()) return sampleManyAvx2(x, y, footprints_m, count, out);
  for (int i = 0; i < count; ++i) out[i] = sample(x[i], y[i], footprints_m[i]);
}

float TexelTiles::texel(std::int64_t ix, std::int64_t iy, int level) const {
  float value;
  function_(ix, iy, texel_[level], 1, &value);
  return value;
}

namespace {

// The next level's bilinear interpolation at node (ix, iy) of a level: from
// the next level's nodes at and after (ix / 2, iy / 2), node(du, dv) for du, dv
// in {0, 1}; a node its position does not need (an even index lies on a
// coarse node) is not read.
template <typename Node>
float coarserAt(std::int64_t ix, std::int64_t iy, const Node& node) {
  const bool oddX = (ix & 1) != 0, oddY = (iy & 1) != 0;
  const double a = oddX ? 0.5 : 0.0, b = oddY ? 0.5 : 0.0;
  const double c10 = oddX ? node(1, 0) : 0.0, c01 = oddY ? node(0, 1) : 0.0;
  const double c11 = oddX && oddY ? node(1, 1) : 0.0;
  return static_cast<float>(bilinearOf(a, b, node(0, 0), c10, c01, c11));
}

}  // namespace

TexelTiles::TexelPair TexelTiles::texelPair(std::int64_t ix, std::int64_t iy, int level) const {
  const std::int64_t cx = ix >> 1, cy = iy >> 1;
  return {texel(ix, iy, level), coarserAt(ix, iy, [&](int du, int dv) { return texel(cx + du, cy + dv, level + 1); })};
}

void TexelTiles::fill(Tile& tile, const Key& key) const {
  // The next level's nodes under the tile first (half as many per side, plus the shared one): from that
  // level's tile where the cache holds it (a quarter of it), else computed, to the same values.
  constexpr int kCoarse = kTile / 2 + 1;
  std::array<float, kCoarse * kCoarse> coarse;
  const std::int64_t cx0 = key.tx * kTile / 2, cy0 = key.ty * kTile / 2;
  const auto coarser = tiles_.find(Key{key.tx >> 1, key.ty >> 1, key.level + 1});
  const TexelPair* quarter = nullptr;
  Layout coarseLayout;
  if (coarser != tiles_.end()) {
    coarseLayout = layoutOf(coarser->second->alongY);
    quarter = coarser->second->texels.data() + coarseLayout.at((key.tx & 1) * (kTile / 2), (key.ty & 1) * (kTile / 2));
  }
  for (int v = 0; v < kCoarse; ++v) {
    if (quarter == nullptr) {
      function_(cx0, cy0 + v, texel_[key.level + 1], kCoarse, &coarse[v * kCoarse]);
      continue;
    }
    for (int u = 0; u < kCoarse; ++u) coarse[v * kCoarse + u] = quarter[coarseLayout.at(u, v)].value;
  }
  std::array<float, kTile + 1> values;
  tile.alongY = alongY_;
  for (int v = 0; v <= kTile; ++v) {
    function_(key.tx * kTile, key.ty * kTile + v, texel_[key.level], kTile + 1, values.data());
    for (int u = 0; u <= kTile; ++u) {
      const float* c = &coarse[(v / 2) * kCoarse + u / 2];
      tile.texels[layout_.at(u, v)] = {values[u],
                                       coarserAt(u, v, [&](int du, int dv) { return c[dv * kCoarse + du]; })};
    }
  }
}

void TexelTiles::transpose(Tile& tile) {
  for (int v = 0; v <= kTile; ++v)
    for (int u = v + 1; u <= kTile; ++u) std::swap(tile.texels[v * (kTile + 1) + u], tile.texels[u * (kTile + 1) + v]);
  tile.alongY = !tile.alongY;
}

std::vector<TexelTiles::TileRange> TexelTiles::tileRanges(const std::vector<TexelRegion>& regions) const {
  // A region wider than this many tiles at one level is left to sample()'s
  // direct evaluation: a guard against a degenerate region allocating a huge grid.
  constexpr std::int64_t kMaxTilesPerRegion = 4096;
  std::vector<TileRange> ranges;
  ranges.reserve(3 * regions.size());
  for (const TexelRegion& region : regions) {
    const Eigen::AlignedBox2d& box = region.box;
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) continue;
    int lowest, highest;
    double fraction;
    levels(region.minFootprint_m, lowest, fraction);
    levels(region.maxFootprint_m, highest, fraction);  // the blend's next level is in each texel's pair
    for (int level = lowest; level <= highest; ++level) {
      const TileRange range{
          texelIndex(box.min().x(), level) >> kTileBits, texelIndex(box.min().y(), level) >> kTileBits,
          texelIndex(box.max().x(), level) >> kTileBits, texelIndex(box.max().y(), level) >> kTileBits, level};
      if ((range.tx1 - range.tx0 + 1) * (range.ty1 - range.ty0 + 1) <= kMaxTilesPerRegion) ranges.push_back(range);
    }
  }
  return ranges;
}

void TexelTiles::require(const std::vector<TexelRegion>& regions, int threads, const Eigen::Vector2d& rowDirection) {
  constexpr double kSwitch = 1.2;  // tan(50 deg)
  const double along = std::abs(alongY_ ? rowDirection.y() : rowDirection.x());
  const double across = std::abs(alongY_ ? rowDirection.x() : rowDirection.y());
  if (across > kSwitch * along) alongY_ = !alongY_, layout_ = layoutOf(alongY_);
  ++images_;
  layOut(tileRanges(regions));
  // Find or make every tile the grids list; fill the new ones on all threads.
  std::vector<std::pair<Key, Tile*>> missing;
  for (int level = 0; level < kLevels; ++level) {
    LevelGrid& grid = grids_[level];
    for (std::int64_t row = 0; row < grid.height; ++row) {
      for (std::int64_t column = 0; column < grid.width; ++column) {
        const TexelPair*& slot = grid.texels[row * grid.width + column];
        if (slot == nullptr) continue;
        const Key key{grid.tx0 + column, grid.ty0 + row, level};
        auto found = tiles_.find(key);
        if (found == tiles_.end()) {
          found = tiles_.emplace(key, std::make_unique<Tile>()).first;
          found->second->texels.resize((kTile + 1) * (kTile + 1));  // filled below; the grid points at its data
          missing.emplace_back(key, found->second.get());
        } else if (found->second->alongY != alongY_) {
          transpose(*found->second);  // this image reads its tiles in the current layout
        }
        found->second->lastUsed = images_;
        slot = found->second->texels.data();
      }
    }
  }
  // Coarse levels first: a tile then reads its next level's nodes from that level's tile, already filled.
  std::stable_sort(missing.begin(), missing.end(),
                   [](const auto& a, const auto& b) { return a.first.level > b.first.level; });
  for (std::size_t begin = 0; begin < missing.size();) {
    std::size_t end = begin;
    while (end < missing.size() && missing[end].first.level == missing[begin].first.level) ++end;
    parallelFor(static_cast<int>(begin), static_cast<int>(end), threads, 1,
                [&](int i) { fill(*missing[i].second, missing[i].first); });
    begin = end;
  }
  std::erase_if(tiles_, [&](const auto& entry) { return entry.second->lastUsed <= images_ - keep_; });
}

void TexelTiles::layOut(const std::vector<TileRange>& ranges) {
  // Each level's grid spans the bounding box of its ranges; a slot a range
  // covers holds this marker until require() points it at its tile's texels.
  static const TexelPair kWanted{};
  std::array<TileRange, kLevels> bounds;
  std::array<bool, kLevels> used{};
  for (const TileRange& r : ranges) {
    TileRange& b = bounds[r.level];
    if (!used[r.level]) {
      b = r, used[r.level] = true;
      continue;
    }
    b.tx0 = std::min(b.tx0, r.tx0), b.ty0 = std::min(b.ty0, r.ty0);
    b.tx1 = std::max(b.tx1, r.tx1), b.ty1 = std::max(b.ty1, r.ty1);
  }
  for (int level = 0; level < kLevels; ++level) {
    LevelGrid& grid = grids_[level];
    grid = LevelGrid{};
    if (!used[level]) continue;
    grid.tx0 = bounds[level].tx0, grid.ty0 = bounds[level].ty0;
    grid.width = bounds[level].tx1 - grid.tx0 + 1, grid.height = bounds[level].ty1 - grid.ty0 + 1;
    grid.texels.assign(static_cast<std::size_t>(grid.width * grid.height), nullptr);
  }
  for (const TileRange& r : ranges) {
    LevelGrid& grid = grids_[r.level];
    for (std::int64_t ty = r.ty0; ty <= r.ty1; ++ty)
      for (std::int64_t tx = r.tx0; tx <= r.tx1; ++tx)
        grid.texels[(ty - grid.ty0) * grid.width + (tx - grid.tx0)] = &kWanted;
  }
}

}  // namespace lrsvo
