#pragma once

#include <Eigen/Geometry>

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// The transform of a secondary camera relative to the base camera, shared by
// every pose of a window: s = (x, y, z, roll, pitch, yaw), where (x, y, z) = c
// is the secondary camera's centre in the base camera frame and
// R_s = Rz(yaw) Ry(pitch) Rx(roll) rotates base-frame vectors into the
// secondary frame: X_c1 = R_s (X_c0 - c). Euclidean, so each of the six
// numbers can carry bounds (docs/method.md: bounding c, not t_s = -R_s c).
class VertexStereoExtrinsic : public VectorVertex<6> {
 public:
  static constexpr const char* kTypeTag = "STEREO_EXTRINSIC";
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  explicit VertexStereoExtrinsic(int id = -1, const Vector6& parameters = Vector6::Zero());

  Eigen::Vector3d centre() const { return estimate_.head<3>(); }
  // R_s and its factors Rx(roll), Ry(pitch), Rz(yaw), kept up to date with
  // the estimate: every projection edge of a window reads them.
  const Eigen::Matrix3d& rotation() const { return rotation_; }
  const Eigen::Matrix3d& rollRotation() const { return roll_; }
  const Eigen::Matrix3d& pitchRotation() const { return pitch_; }
  const Eigen::Matrix3d& yawRotation() const { return yaw_; }
  // The rigid transform X_c1 = R_s (X_c0 - c), secondary-from-base.
  Eigen::Isometry3d secondaryFromBase() const;
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexStereoExtrinsic>(*this); }

 protected:
  void estimateChanged() override;

 private:
  Eigen::Matrix3d rotation_, roll_, pitch_, yaw_;
};

// Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d rotationFromRollPitchYaw(double roll, double pitch, double yaw);

// The secondary-from-base transform of the six parameters s = (c, roll, pitch, yaw).
Eigen::Isometry3d secondaryFromBase(const VertexStereoExtrinsic::Vector6& parameters);

}  // namespace lrsvo
