#pragma once

#include <map>
#include <vector>

#include <Eigen/Geometry>

namespace lrsvo {

// What an initialiser has built so far: base-camera poses (camera-from-world)
// of consecutive frames from the first, and points by track id, in one frame
// and one unit (the world is the first base camera's frame).
struct SparseMap {
  std::vector<Eigen::Isometry3d> cameraFromWorld;
  std::map<int, Eigen::Vector3d> points;

  // Multiplies every point and camera position by `factor` (a change of unit).
  void scale(double factor);
};

}  // namespace lrsvo
