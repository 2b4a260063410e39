#include "lrsvo/frontend/odometry/rig_extrinsic.h"

#include <algorithm>
#include <cmath>

namespace lrsvo {

Eigen::Vector3d rollPitchYawFromRotation(const Eigen::Matrix3d& r) {
  // Rz(yaw) Ry(pitch) Rx(roll) has first column (cy cp, sy cp, -sp) and last row (-sp, cp sr, cp cr).
  const double pitch = -std::asin(std::clamp(r(2, 0), -1.0, 1.0));
  return {std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0))};
}

VertexStereoExtrinsic::Vector6 extrinsicFromPoses(const Eigen::Isometry3d& frameFromBase,
                                                  const Eigen::Isometry3d& frameFromSecondary) {
  const Eigen::Isometry3d baseFromSecondary = frameFromBase.inverse() * frameFromSecondary;
  VertexStereoExtrinsic::Vector6 s;
  s.head<3>() = baseFromSecondary.translation();
  s.tail<3>() = rollPitchYawFromRotation(baseFromSecondary.linear().transpose());
  return s;
}

}  // namespace lrsvo
