#include "lrsvo/vertices/vertex_pose.h"

#include <cmath>

#include "lrsvo/graph/error.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

VertexPose::VertexPose(int id, const Eigen::Isometry3d& cameraFromWorld) : BaseVertex<6>(id) {
  setCameraFromWorld(cameraFromWorld);
}

Eigen::Isometry3d VertexPose::cameraFromWorld() const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation_;
  pose.translation() = translation_;
  return pose;
}

void VertexPose::setCameraFromWorld(const Eigen::Isometry3d& pose) {
  quaternion_ = Eigen::Quaterniond(pose.linear()).normalized();
  rotation_ = quaternion_.toRotationMatrix();
  translation_ = pose.translation();
}

void VertexPose::getEstimate(double* values) const {
  const Eigen::Quaterniond& q = quaternion_;
  values[0] = translation_.x();
  values[1] = translation_.y();
  values[2] = translation_.z();
  values[3] = q.x();
  values[4] = q.y();
  values[5] = q.z();
  values[6] = q.w();
}

void VertexPose::setEstimate(const double* values) {
  const Eigen::Quaterniond q(values[6], values[3], values[4], values[5]);
  if (std::abs(q.norm() - 1.0) > 1e-6)
    throw Error("POSE_SE3 " + std::to_string(id()) + ": quaternion norm " + std::to_string(q.norm()) + " is not 1");
  translation_ = Eigen::Vector3d(values[0], values[1], values[2]);
  quaternion_ = q;
  rotation_ = q.normalized().toRotationMatrix();
}

void VertexPose::oplus(const double* delta) {
  const Eigen::Matrix3d dR = expSO3(Eigen::Vector3d(delta[3], delta[4], delta[5]));
  translation_ = dR * translation_ + Eigen::Vector3d(delta[0], delta[1], delta[2]);
  // Normalising the quaternion keeps rounding from accumulating over many updates.
  quaternion_ = (Eigen::Quaterniond(dR) * quaternion_).normalized();
  rotation_ = quaternion_.toRotationMatrix();
}

}  // namespace lrsvo
