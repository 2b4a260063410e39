#include "lrsvo/edges/secondary_projection.h"

#include <istream>
#include <ostream>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

SecondaryProjectionJacobians secondaryProjectionJacobians(const VertexPose& pose, const Eigen::Vector3d& point,
                                                          const VertexStereoExtrinsic& extrinsic, double kappa,
                                                          const PinholeIntrinsics& intrinsics) {
  const Eigen::Vector3d c = extrinsic.centre();
  const Eigen::Vector3d base = pose.rotation() * point + pose.translation();
  const Eigen::Vector3d offset = base - c / kappa;
  const Eigen::Matrix3d& rs = extrinsic.rotation();
  const Eigen::Vector3d secondary = rs * offset;
  const Eigen::Matrix<double, 2, 3> dxdp = intrinsics.projectJacobian(secondary);
  const Eigen::Matrix<double, 2, 3> dxdBase = dxdp * rs;
  SecondaryProjectionJacobians jacobians;
  jacobians.pose.leftCols<3>() = dxdBase;
  jacobians.pose.rightCols<3>() = -dxdBase * skew(base);
  jacobians.point = dxdBase * pose.rotation();
  jacobians.extrinsic.leftCols<3>() = -dxdBase / kappa;
  // R_s = Rz(yaw) Ry(pitch) Rx(roll); each angle's derivative inserts its
  // axis' cross product at that factor.
  const Eigen::Matrix3d& rx = extrinsic.rollRotation();
  const Eigen::Matrix3d& ry = extrinsic.pitchRotation();
  const Eigen::Matrix3d& rz = extrinsic.yawRotation();
  jacobians.extrinsic.col(3) = dxdp * (rs * Eigen::Vector3d::UnitX().cross(offset));
  jacobians.extrinsic.col(4) = dxdp * (rz * (ry * Eigen::Vector3d::UnitY().cross(rx * offset)));
  jacobians.extrinsic.col(5) = dxdp * Eigen::Vector3d::UnitZ().cross(secondary);
  jacobians.kappa = dxdBase * c / (kappa * kappa);
  return jacobians;
}

void SecondaryCamera::write(std::ostream& out) const {
  out << ' ' << index;
  intrinsics.write(out);
}

void SecondaryCamera::read(std::istream& in, const char* what) {
  if (!(in >> index) || index < 1) throw Error(std::string(what) + ": camera index must be an integer >= 1");
  intrinsics.read(in, what);
}

}  // namespace lrsvo
