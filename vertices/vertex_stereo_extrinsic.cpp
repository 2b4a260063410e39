#include "vertices/vertex_stereo_extrinsic.h"

#include <Eigen/Geometry>

#include "graph/registry.h"

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
  estimate_ = parameters;
}

Eigen::Matrix3d VertexStereoExtrinsic::rotation() const {
  return rotationFromRollPitchYaw(estimate_[3], estimate_[4], estimate_[5]);
}

Eigen::Isometry3d VertexStereoExtrinsic::secondaryFromBase() const { return lrsvo::secondaryFromBase(estimate_); }

LRSVO_REGISTER_TYPE(Vertex, VertexStereoExtrinsic);

}  // namespace lrsvo
