#include "vertices/vertex_stereo_extrinsic.h"

#include <Eigen/Geometry>

#include "graph/registry.h"

namespace lrsvo {

Eigen::Matrix3d rotationFromRollPitchYaw(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

VertexStereoExtrinsic::VertexStereoExtrinsic(int id, const Vector6& parameters) : VectorVertex<6>(id) {
  estimate_ = parameters;
}

Eigen::Matrix3d VertexStereoExtrinsic::rotation() const {
  return rotationFromRollPitchYaw(estimate_[3], estimate_[4], estimate_[5]);
}

LRSVO_REGISTER_TYPE(Vertex, VertexStereoExtrinsic);

}  // namespace lrsvo
