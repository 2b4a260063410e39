#pragma once

#include <Eigen/Geometry>

#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// (roll, pitch, yaw) with R = Rz(yaw) Ry(pitch) Rx(roll), pitch in [-pi/2, pi/2];
// the inverse of rotationFromRollPitchYaw away from pitch = +-pi/2.
Eigen::Vector3d rollPitchYawFromRotation(const Eigen::Matrix3d& rotation);

// The extrinsic s = (c, roll, pitch, yaw) of a secondary camera from both
// cameras' poses in a common frame (e.g. body-from-sensor, EuRoC's T_BS):
// c = the secondary's centre in the base frame, R_s = secondary-from-base.
VertexStereoExtrinsic::Vector6 extrinsicFromPoses(const Eigen::Isometry3d& frameFromBase,
                                                  const Eigen::Isometry3d& frameFromSecondary);

}  // namespace lrsvo
