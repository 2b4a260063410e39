#pragma once

#include <cmath>

#include <Eigen/Geometry>

#include "lrsvo/graph/vertex.h"

namespace lrsvo {

// Rz(yaw) Ry(pitch) Rx(roll) in any scalar type.
template <typename T>
Eigen::Matrix<T, 3, 3> rollPitchYawRotation(const T& roll, const T& pitch, const T& yaw) {
  using std::cos;
  using std::sin;
  const T cr = cos(roll), sr = sin(roll), cp = cos(pitch), sp = sin(pitch), cy = cos(yaw), sy = sin(yaw);
  Eigen::Matrix<T, 3, 3> r;
  r << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  return r;
}

// The six extrinsic parameters s = (c, roll, pitch, yaw) with R_s, in any
// scalar type: what automatically differentiated edges read of a VertexStereoExtrinsic.
template <typename T>
struct ExtrinsicState {
  Eigen::Matrix<T, 6, 1> parameters;
  Eigen::Matrix<T, 3, 3> rotation;

  static ExtrinsicState fromParameters(const Eigen::Matrix<T, 6, 1>& s) {
    return {s, rollPitchYawRotation<T>(s[3], s[4], s[5])};
  }
};

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

  // For graph/autodiff_edge.h (in place of VectorVertex's, which give the
  // parameters alone): the parameters with R_s, as they are and after oplus(delta).
  ExtrinsicState<double> state() const { return {estimate_, rotation_}; }
  template <typename T>
  ExtrinsicState<T> perturbed(const Eigen::Matrix<T, 6, 1>& delta) const {
    return ExtrinsicState<T>::fromParameters(delta + estimate_);
  }

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
