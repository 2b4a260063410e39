#include "lrsvo/sim/scene_point_grid.h"

#include <cmath>
#include <random>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

constexpr double kWorldLimit_m = 1e9;  // keeps every cell index well inside int64

}  // namespace

ScenePointGrid::ScenePointGrid(const std::vector<Eigen::AlignedBox2d>& regions, double cellSize_m)
    : cellSize_m_(cellSize_m) {
  if (!(std::isfinite(cellSize_m) && cellSize_m > 0.0))
    throw Error("scene point grid: the cell size must be finite and > 0, got " + std::to_string(cellSize_m));
  if (regions.empty()) throw Error("scene point grid: needs at least one region");
  for (const Eigen::AlignedBox2d& region : regions) {
    if (!(region.min().cwiseAbs().maxCoeff() <= kWorldLimit_m && region.max().cwiseAbs().maxCoeff() <= kWorldLimit_m))
      throw Error("scene point grid: a region is empty, not finite or beyond +-1e9 m");
    const Key low = key(region.min().x(), region.min().y()), high = key(region.max().x(), region.max().y());
    for (std::int64_t ix = low.first; ix <= high.first; ++ix)
      for (std::int64_t iy = low.second; iy <= high.second; ++iy) cells_[{ix, iy}];
  }
}

ScenePointGrid::Key ScenePointGrid::key(double x, double y) const {
  return {static_cast<std::int64_t>(std::floor(x / cellSize_m_)),
          static_cast<std::int64_t>(std::floor(y / cellSize_m_))};
}

double ScenePointGrid::area() const { return static_cast<double>(cells_.size()) * cellSize_m_ * cellSize_m_; }

void ScenePointGrid::sample(const Terrain& terrain, int count, std::uint64_t seed) {
  if (count < 0) throw Error("scene point grid: the point count must be >= 0, got " + std::to_string(count));
  // Each point picks a cell uniformly, so the points are uniform over the union of cells.
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, cells_.size() - 1);
  std::vector<int> perCell(cells_.size(), 0);
  for (int i = 0; i < count; ++i) ++perCell[pick(rng)];
  points_.clear();
  points_.reserve(count);
  std::size_t index = 0;
  for (auto& [cellKey, range] : cells_) {
    const Eigen::Vector2d min(cellKey.first * cellSize_m_, cellKey.second * cellSize_m_);
    const std::uint64_t cellSeed =
        mixSeed(seed, static_cast<std::uint64_t>(cellKey.first), static_cast<std::uint64_t>(cellKey.second));
    range.begin = static_cast<int>(points_.size());
    for (const Eigen::Vector3d& point :
         terrain.samplePoints(min, min + Eigen::Vector2d::Constant(cellSize_m_), perCell[index++], cellSeed))
      points_.push_back(point);
    range.end = static_cast<int>(points_.size());
  }
}

std::vector<int> ScenePointGrid::pointsNear(const Eigen::AlignedBox2d& box) const {
  std::vector<int> indices;
  const Key low = key(box.min().x(), box.min().y()), high = key(box.max().x(), box.max().y());
  for (std::int64_t ix = low.first; ix <= high.first; ++ix) {
    for (std::int64_t iy = low.second; iy <= high.second; ++iy) {
      const auto found = cells_.find({ix, iy});
      if (found == cells_.end()) continue;
      for (int i = found->second.begin; i < found->second.end; ++i) indices.push_back(i);
    }
  }
  return indices;
}

}  // namespace lrsvo
