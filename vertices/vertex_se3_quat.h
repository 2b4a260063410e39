#pragma once

#include <string>

#include <Eigen/Geometry>

#include "lrsvo/graph/vertex.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

// A world-from-body pose X_w = q X_b + t in any scalar type: what
// automatically differentiated edges read of a VertexSE3Quat.
template <typename T>
struct QuaternionPoseState {
  Eigen::Quaternion<T> rotation;  // unit
  Eigen::Matrix<T, 3, 1> translation;
};

// A pose in space, world-from-body as g2o's VERTEX_SE3:QUAT: X_w = R X_b + t.
// Update delta = (dt, dphi): t <- t + dt (world frame), R <- R Exp(dphi)
// (body frame). Stored as x y z qx qy qz qw; the quaternion is kept as given,
// so a save/load round trip is exact, and used normalised.
class VertexSE3Quat : public BaseVertex<6> {
 public:
  static constexpr const char* kTypeTag = "POSE_SE3_QUAT";
  // Quaternions read from text written with 6 decimals (as g2o's example
  // files are) are off unit norm by up to about 1e-6; ten times that is accepted.
  static constexpr double kQuaternionNormTolerance = 1e-5;

  explicit VertexSE3Quat(int id = -1, const Eigen::Isometry3d& worldFromBody = Eigen::Isometry3d::Identity());

  const Eigen::Vector3d& translation() const { return translation_; }
  // The rotation of the normalised quaternion, and that quaternion.
  const Eigen::Matrix3d& rotation() const { return rotation_; }
  const Eigen::Quaterniond& unitQuaternion() const { return unitQuaternion_; }
  // The quaternion as given.
  const Eigen::Quaterniond& quaternion() const { return quaternion_; }
  Eigen::Isometry3d worldFromBody() const;
  void setWorldFromBody(const Eigen::Isometry3d& pose);
  // Throws lrsvo::Error unless the quaternion is within kQuaternionNormTolerance of unit norm.
  void setPose(const Eigen::Vector3d& translation, const Eigen::Quaterniond& quaternion);

  int estimateSize() const override { return 7; }
  void getEstimate(double* values) const override;
  // Throws lrsvo::Error on a non-finite value or a quaternion off unit norm.
  void setEstimate(const double* values) override;
  void oplus(const double* delta) override;

  // For graph/autodiff_edge.h: the pose, and the pose after oplus(delta) in any scalar type.
  QuaternionPoseState<double> state() const { return {unitQuaternion_, translation_}; }
  template <typename T>
  QuaternionPoseState<T> perturbed(const Eigen::Matrix<T, 6, 1>& delta) const {
    return {unitQuaternion_.cast<T>() * quaternionExp<T>(delta.template tail<3>()),
            delta.template head<3>() + translation_};
  }
  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexSE3Quat>(*this); }

 private:
  Eigen::Vector3d translation_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond quaternion_ = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond unitQuaternion_ = Eigen::Quaterniond::Identity();  // cached
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();              // cached
};

// Throws lrsvo::Error naming `what` unless q is finite and within
// VertexSE3Quat::kQuaternionNormTolerance of unit norm.
void checkUnitQuaternion(const Eigen::Quaterniond& q, const std::string& what);

}  // namespace lrsvo
