#include "lrsvo/vertices/vertex_se3_quat.h"

#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

void checkUnitQuaternion(const Eigen::Quaterniond& q, const std::string& what) {
  if (!q.coeffs().allFinite()) throw Error(what + ": quaternion is not finite");
  if (std::abs(q.norm() - 1.0) > VertexSE3Quat::kQuaternionNormTolerance)
    throw Error(what + ": quaternion norm " + std::to_string(q.norm()) + " is not 1");
}

VertexSE3Quat::VertexSE3Quat(int id, const Eigen::Isometry3d& worldFromBody) : BaseVertex<6>(id) {
  setWorldFromBody(worldFromBody);
}

Eigen::Isometry3d VertexSE3Quat::worldFromBody() const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation_;
  pose.translation() = translation_;
  return pose;
}

void VertexSE3Quat::setWorldFromBody(const Eigen::Isometry3d& pose) {
  setPose(pose.translation(), Eigen::Quaterniond(pose.linear()).normalized());
}

void VertexSE3Quat::setPose(const Eigen::Vector3d& translation, const Eigen::Quaterniond& quaternion) {
  if (!translation.allFinite()) throw Error(std::string(kTypeTag) + " " + std::to_string(id()) + ": not finite");
  checkUnitQuaternion(quaternion, std::string(kTypeTag) + " " + std::to_string(id()));
  translation_ = translation;
  quaternion_ = quaternion;
  unitQuaternion_ = quaternion.normalized();
  rotation_ = unitQuaternion_.toRotationMatrix();
}

void VertexSE3Quat::getEstimate(double* values) const {
  Eigen::Map<Eigen::Vector3d>{values} = translation_;
  Eigen::Map<Eigen::Vector4d>{values + 3} = quaternion_.coeffs();  // Eigen's order: x y z w
}

void VertexSE3Quat::setEstimate(const double* values) {
  setPose(Eigen::Vector3d(values[0], values[1], values[2]),
          Eigen::Quaterniond(values[6], values[3], values[4], values[5]));
}

void VertexSE3Quat::oplus(const double* delta) {
  translation_ += Eigen::Vector3d(delta[0], delta[1], delta[2]);
  // Normalising keeps rounding from accumulating over many updates.
  quaternion_ =
      (unitQuaternion_ * Eigen::Quaterniond(expSO3(Eigen::Vector3d(delta[3], delta[4], delta[5])))).normalized();
  unitQuaternion_ = quaternion_;
  rotation_ = unitQuaternion_.toRotationMatrix();
}

}  // namespace lrsvo
