#include "lrsvo/frontend/odometry/sparse_map.h"

namespace lrsvo {

void SparseMap::scale(double factor) {
  // X_c = R X + t: scaling X and t scales X_c, and projections do not change.
  for (Eigen::Isometry3d& pose : cameraFromWorld) pose.translation() *= factor;
  for (auto& [track, point] : points) point *= factor;
}

}  // namespace lrsvo
