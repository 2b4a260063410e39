#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

#include <Eigen/Geometry>

namespace lrsvo {

Eigen::Matrix3d rotationFromRollPitchYaw(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d secondaryFromBase(const VertexStereoExtrinsic::Vector6& parameters) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = rotationFromRollPitchYaw(parameters[3], parameters[4], parameters[5]);
  transform.translation() = -transform.linear() * parameters.head<3>();
  return transform;
}

VertexStereoExtrinsic::VertexStereoExtrinsic(int id, const Vector6& parameters) : VectorVertex<6>(id) {
  setEstimateVector(parameters);
}

void VertexStereoExtrinsic::estimateChanged() {
  roll_ = rotationFromRollPitchYaw(estimate_[3], 0.0, 0.0);
  pitch_ = rotationFromRollPitchYaw(0.0, estimate_[4], 0.0);
  yaw_ = rotationFromRollPitchYaw(0.0, 0.0, estimate_[5]);
  rotation_ = yaw_ * pitch_ * roll_;
}

Eigen::Isometry3d VertexStereoExtrinsic::secondaryFromBase() const {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = rotation_;
  transform.translation() = -rotation_ * estimate_.head<3>();
  return transform;
}

}  // namespace lrsvo
