#include "lrsvo/vertices/vertex_se2.h"

#include <cmath>
#include <numbers>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

double wrapAngle(double angle) {
  // remainder() lands in [-pi, pi]; -pi is the same heading as pi.
  const double wrapped = std::remainder(angle, 2.0 * std::numbers::pi);
  return wrapped <= -std::numbers::pi ? wrapped + 2.0 * std::numbers::pi : wrapped;
}

Eigen::Isometry2d VertexSE2::worldFromBody() const {
  Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
  pose.linear() = Eigen::Rotation2Dd(pose_[2]).toRotationMatrix();
  pose.translation() = pose_.head<2>();
  return pose;
}

void VertexSE2::getEstimate(double* values) const { Eigen::Map<Eigen::Vector3d>{values} = pose_; }

void VertexSE2::setEstimate(const double* values) {
  const Eigen::Map<const Eigen::Vector3d> pose(values);
  if (!pose.allFinite()) throw Error(std::string(kTypeTag) + " " + std::to_string(id()) + ": value is not finite");
  pose_ = pose;
}

void VertexSE2::oplus(const double* delta) {
  pose_[0] += delta[0];
  pose_[1] += delta[1];
  pose_[2] = wrapAngle(pose_[2] + delta[2]);
}

}  // namespace lrsvo
