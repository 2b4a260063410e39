#pragma once

#include <Eigen/Geometry>

#include "lrsvo/graph/vertex.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

// A camera-from-world transform X_c = R X_w + t in any scalar type: what
// automatically differentiated edges read of a VertexPose.
template <typename T>
struct RigidState {
  Eigen::Matrix<T, 3, 3> rotation;
  Eigen::Matrix<T, 3, 1> translation;
};

// A camera pose as camera-from-world T = (R, t): X_c = R X_w + t.
// Update delta = (dt, dphi): R <- Exp(dphi) R, t <- Exp(dphi) t + dt, i.e.
// T <- Exp(delta) T on the left, with rotation and translation decoupled.
// Stored in files as tx ty tz qx qy qz qw; the quaternion is kept as given,
// so a save/load round trip is exact.
class VertexPose : public BaseVertex<6> {
 public:
  static constexpr const char* kTypeTag = "POSE_SE3";
  explicit VertexPose(int id = -1, const Eigen::Isometry3d& cameraFromWorld = Eigen::Isometry3d::Identity());

  const Eigen::Matrix3d& rotation() const { return rotation_; }
  const Eigen::Vector3d& translation() const { return translation_; }
  Eigen::Isometry3d cameraFromWorld() const;
  void setCameraFromWorld(const Eigen::Isometry3d& pose);
  // Camera centre in the world frame, -R^T t.
  Eigen::Vector3d centre() const { return -rotation_.transpose() * translation_; }

  int estimateSize() const override { return 7; }
  void getEstimate(double* values) const override;
  // Throws lrsvo::Error unless the quaternion has a norm near 1.
  void setEstimate(const double* values) override;
  void oplus(const double* delta) override;

  // For graph/autodiff_edge.h: the pose, and the pose after oplus(delta) in any scalar type.
  RigidState<double> state() const { return {rotation_, translation_}; }
  template <typename T>
  RigidState<T> perturbed(const Eigen::Matrix<T, 6, 1>& delta) const {
    const Eigen::Matrix<T, 3, 3> dR = expSO3Of<T>(delta.template tail<3>());
    // Mixed dual-double products: the estimate's numbers carry no derivatives to multiply.
    return {dR * rotation_, dR * translation_ + delta.template head<3>()};
  }

  const char* typeTag() const override { return kTypeTag; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexPose>(*this); }

 private:
  Eigen::Quaterniond quaternion_ = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();  // of quaternion_, cached
  Eigen::Vector3d translation_ = Eigen::Vector3d::Zero();
};

}  // namespace lrsvo
