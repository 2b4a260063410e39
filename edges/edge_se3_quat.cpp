#include "lrsvo/edges/edge_se3_quat.h"

#include "lrsvo/graph/edge_io.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeSE3Quat, 6, VertexSE3Quat, VertexSE3Quat>;

namespace {

// The unit quaternion of E = Z^-1 Ri^T Rj with w >= 0 (q and -q are the same rotation).
Eigen::Quaterniond errorQuaternion(const Eigen::Quaterniond& inverseMeasurement, const VertexSE3Quat& from,
                                   const VertexSE3Quat& to) {
  Eigen::Quaterniond q = inverseMeasurement * from.unitQuaternion().conjugate() * to.unitQuaternion();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return q;
}

}  // namespace

void EdgeSE3Quat::setRelativePose(const Eigen::Vector3d& translation, const Eigen::Quaterniond& quaternion) {
  if (!translation.allFinite()) throw Error(std::string(kTypeTag) + ": translation is not finite");
  checkUnitQuaternion(quaternion, kTypeTag);
  relativeTranslation_ = translation;
  relativeQuaternion_ = quaternion;
  inverseUnitQuaternion_ = quaternion.normalized().conjugate();
  inverseRotation_ = inverseUnitQuaternion_.toRotationMatrix();
}

void EdgeSE3Quat::setRelativePose(const Eigen::Isometry3d& pose) {
  setRelativePose(pose.translation(), Eigen::Quaterniond(pose.linear()).normalized());
}

void EdgeSE3Quat::computeJacobians() {
  // Under VertexSE3Quat's update (t + dt, R Exp(dphi)):
  //   translation: d/dt_i = -Rz^T Ri^T, d/dphi_i = Rz^T [v]x with v = Ri^T (t_j - t_i), d/dt_j = Rz^T Ri^T;
  //   rotation: E becomes E Exp(w) with w = dphi_j - (Ri^T Rj)^T dphi_i, and the vector part of
  //   q_E (1, w/2) moves by M w, M = (w_E I + [q_E]x) / 2.
  const VertexSE3Quat& from = *vertexAs<0>();
  const VertexSE3Quat& to = *vertexAs<1>();
  const Eigen::Matrix3d toResidual = inverseRotation_ * from.rotation().transpose();
  const Eigen::Vector3d inFrom = from.rotation().transpose() * (to.translation() - from.translation());
  const Eigen::Quaterniond q = errorQuaternion(inverseUnitQuaternion_, from, to);
  const Eigen::Matrix3d M = 0.5 * (q.w() * Eigen::Matrix3d::Identity() + skew(q.vec()));
  const Eigen::Matrix3d relativeRotation = from.rotation().transpose() * to.rotation();

  jacobian<0>().topLeftCorner<3, 3>() = -toResidual;
  jacobian<0>().topRightCorner<3, 3>() = inverseRotation_ * skew(inFrom);
  jacobian<0>().bottomLeftCorner<3, 3>().setZero();
  jacobian<0>().bottomRightCorner<3, 3>() = -M * relativeRotation.transpose();
  jacobian<1>().topLeftCorner<3, 3>() = toResidual;
  jacobian<1>().topRightCorner<3, 3>().setZero();
  jacobian<1>().bottomLeftCorner<3, 3>().setZero();
  jacobian<1>().bottomRightCorner<3, 3>() = M;
}

void EdgeSE3Quat::writeData(std::ostream& out) const {
  writeVector(out, relativeTranslation_);
  writeVector(out, relativeQuaternion_.coeffs());
  writeUpperTriangle(out, information());
  writeKernel(out, robustKernel().get());
}

void EdgeSE3Quat::readData(std::istream& in) {
  Eigen::Vector3d translation;
  Eigen::Vector4d quaternion;  // x y z w
  readVector(in, translation, kTypeTag);
  readVector(in, quaternion, kTypeTag);
  Information information;
  readUpperTriangle(in, information, kTypeTag);
  setRelativePose(translation, Eigen::Quaterniond(quaternion));
  setInformation(information);
  setRobustKernel(readKernel(in, kTypeTag));
}

}  // namespace lrsvo
