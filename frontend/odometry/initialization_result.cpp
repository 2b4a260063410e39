#include "lrsvo/frontend/odometry/initialization_result.h"

namespace lrsvo {

bool isBetterStart(const InitializationResult& candidate, const InitializationResult& other) {
  if (candidate.success != other.success) return candidate.success;
  return candidate.rmsReprojectionError_px < other.rmsReprojectionError_px;
}

std::vector<Eigen::Isometry3d> alignToFirstCamera(const std::vector<Eigen::Isometry3d>& trueCameraFromWorld) {
  std::vector<Eigen::Isometry3d> aligned;
  if (trueCameraFromWorld.empty()) return aligned;
  const Eigen::Isometry3d worldFromFirst = trueCameraFromWorld.front().inverse();
  for (const Eigen::Isometry3d& pose : trueCameraFromWorld) aligned.push_back(pose * worldFromFirst);
  return aligned;
}

}  // namespace lrsvo
