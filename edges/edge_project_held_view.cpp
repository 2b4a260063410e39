#include "lrsvo/edges/edge_project_held_view.h"

#include <cmath>
#include <string>

#include "lrsvo/graph/edge_io.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeProjectHeldView, 2, VertexPoint3, VertexScale>;

EdgeProjectHeldView::EdgeProjectHeldView(const PinholeIntrinsics& intrinsics, const Eigen::Isometry3d& cameraFromWorld,
                                         const Eigen::Vector3d& origin)
    : intrinsics_(intrinsics),
      quaternion_(cameraFromWorld.rotation()),
      rotation_(quaternion_.toRotationMatrix()),
      origin_(origin),
      offset_(cameraFromWorld.inverse().translation() - origin) {}

Eigen::Isometry3d EdgeProjectHeldView::cameraFromWorld(double s) const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation_;
  pose.translation() = -(pose.linear() * (origin_ + s * offset_));
  return pose;
}

void EdgeProjectHeldView::computeJacobians() {
  const Eigen::Vector3d centre = origin_ + vertexAs<1>()->kappa() * offset_;
  const Eigen::Matrix<double, 2, 3> dxdX =
      intrinsics_.projectJacobian(rotation_ * (vertexAs<0>()->estimate() - centre)) * rotation_;
  jacobian<0>() = dxdX;
  jacobian<1>() = -dxdX * offset_;
}

void EdgeProjectHeldView::writeParameters(std::ostream& out) const {
  intrinsics_.write(out);
  for (double value : quaternion_.coeffs()) writeNumber(out, value);
  for (double value : origin_) writeNumber(out, value);
  for (double value : offset_) writeNumber(out, value);
}

void EdgeProjectHeldView::readParameters(std::istream& in) {
  intrinsics_.read(in, kTypeTag);
  for (double& value : quaternion_.coeffs()) value = readNumber(in, kTypeTag);
  if (std::abs(quaternion_.norm() - 1.0) > 1e-9)
    throw Error(std::string(kTypeTag) + ": the quaternion must have norm 1");
  rotation_ = quaternion_.toRotationMatrix();
  for (double& value : origin_) value = readNumber(in, kTypeTag);
  for (double& value : offset_) value = readNumber(in, kTypeTag);
}

}  // namespace lrsvo
