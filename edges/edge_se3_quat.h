#pragma once

#include <istream>
#include <ostream>

#include <Eigen/Geometry>

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/vertices/vertex_se3_quat.h"

namespace lrsvo {

// A relative pose in space between vertices i (slot 0) and j (slot 1), as
// g2o's EDGE_SE3:QUAT. The measurement Z (setRelativePose; BaseEdge's
// residual-space measurement() is unused) is pose j seen from pose i. With
// E = Z^-1 (X_i^-1 X_j) the residual is
//   r = (translation of E, vector part of E's unit quaternion taken with w >= 0),
// so the information is ordered translation first, then rotation. Analytic Jacobians.
class EdgeSE3Quat : public AutoDiffEdge<EdgeSE3Quat, 6, VertexSE3Quat, VertexSE3Quat> {
 public:
  static constexpr const char* kTypeTag = "RELATIVE_POSE_SE3_QUAT";
  const char* typeTag() const override { return kTypeTag; }

  const Eigen::Vector3d& relativeTranslation() const { return relativeTranslation_; }
  // The quaternion as given (it is used normalised).
  const Eigen::Quaterniond& relativeQuaternion() const { return relativeQuaternion_; }
  // Throws lrsvo::Error unless the quaternion is within
  // VertexSE3Quat::kQuaternionNormTolerance of unit norm and all is finite.
  void setRelativePose(const Eigen::Vector3d& translation, const Eigen::Quaterniond& quaternion);
  void setRelativePose(const Eigen::Isometry3d& pose);

  template <typename T>
  void residual(const QuaternionPoseState<T>& from, const QuaternionPoseState<T>& to, Eigen::Matrix<T, 6, 1>& r) const {
    const Eigen::Quaternion<T> inverseFrom = from.rotation.conjugate();
    const Eigen::Quaternion<T> inverseMeasurement = inverseUnitQuaternion_.cast<T>();
    const Eigen::Matrix<T, 3, 1> inFrom = inverseFrom * Eigen::Matrix<T, 3, 1>(to.translation - from.translation);
    r.template head<3>() = inverseMeasurement * Eigen::Matrix<T, 3, 1>(inFrom - relativeTranslation_.cast<T>());
    // E's unit quaternion with w >= 0 (q and -q are the same rotation).
    Eigen::Quaternion<T> error = inverseMeasurement * inverseFrom * to.rotation;
    if (error.w() < 0.0) error.coeffs() = -error.coeffs();
    r.template tail<3>() = error.vec();
  }
  void computeJacobians() override;

  // x y z qx qy qz qw, the information's upper triangle, the robust kernel.
  void writeData(std::ostream& out) const override;
  void readData(std::istream& in) override;

 private:
  Eigen::Vector3d relativeTranslation_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond relativeQuaternion_ = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond inverseUnitQuaternion_ = Eigen::Quaterniond::Identity();  // cached Z^-1
  Eigen::Matrix3d inverseRotation_ = Eigen::Matrix3d::Identity();              // cached Rz^T
};

// Its dual-number code is compiled once, in its source file.
extern template class AutoDiffEdge<EdgeSE3Quat, 6, VertexSE3Quat, VertexSE3Quat>;

}  // namespace lrsvo
