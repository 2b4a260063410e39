#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/sim/terrain.h"

namespace lrsvo {

// Scene points on the terrain, uniform over the square cells that a set of
// regions (e.g. every frame's ground footprint) touches, and bucketed by cell
// so that a frame only looks at the points near its own footprint.
class ScenePointGrid {
 public:
  // Throws lrsvo::Error on a non-positive cell size or an empty region list.
  ScenePointGrid(const std::vector<Eigen::AlignedBox2d>& regions, double cellSize_m);

  // Total area of the covered cells (m^2).
  double area() const;
  // Replaces the points by `count` new ones, uniform over the covered cells;
  // the same count and seed give the same points.
  void sample(const Terrain& terrain, int count, std::uint64_t seed);
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  // Indices, ascending, of the points in every covered cell that overlaps `box`.
  std::vector<int> pointsNear(const Eigen::AlignedBox2d& box) const;

 private:
  using Key = std::pair<std::int64_t, std::int64_t>;
  struct Range {
    int begin = 0;
    int end = 0;
  };
  Key key(double x, double y) const;

  double cellSize_m_;
  std::map<Key, Range> cells_;  // covered cells and the indices of their points
  std::vector<Eigen::Vector3d> points_;
};

}  // namespace lrsvo
