#include "lrsvo/edges/secondary_projection.h"

#include <istream>
#include <limits>
#include <ostream>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

Eigen::Vector2d projectSecondary(const VertexPose& pose, const Eigen::Vector3d& point,
                                 const VertexStereoExtrinsic& extrinsic, double kappa,
                                 const PinholeIntrinsics& intrinsics, SecondaryProjectionJacobians* jacobians) {
  if (!(kappa > 0.0)) return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  const auto& s = extrinsic.estimate();
  const Eigen::Vector3d c = s.head<3>();
  const Eigen::Vector3d base = pose.rotation() * point + pose.translation();
  const Eigen::Vector3d offset = base - c / kappa;
  const Eigen::Matrix3d& rs = extrinsic.rotation();
  const Eigen::Vector3d secondary = rs * offset;
  if (jacobians) {
    const Eigen::Matrix<double, 2, 3> dxdp = intrinsics.projectJacobian(secondary);
    const Eigen::Matrix<double, 2, 3> dxdBase = dxdp * rs;
    jacobians->pose.leftCols<3>() = dxdBase;
    jacobians->pose.rightCols<3>() = -dxdBase * skew(base);
    jacobians->point = dxdBase * pose.rotation();
    jacobians->extrinsic.leftCols<3>() = -dxdBase / kappa;
    // R_s = Rz(yaw) Ry(pitch) Rx(roll); each angle's derivative inserts its
    // axis' cross product at that factor.
    const Eigen::Matrix3d& rx = extrinsic.rollRotation();
    const Eigen::Matrix3d& ry = extrinsic.pitchRotation();
    const Eigen::Matrix3d& rz = extrinsic.yawRotation();
    jacobians->extrinsic.col(3) = dxdp * (rs * Eigen::Vector3d::UnitX().cross(offset));
    jacobians->extrinsic.col(4) = dxdp * (rz * (ry * Eigen::Vector3d::UnitY().cross(rx * offset)));
    jacobians->extrinsic.col(5) = dxdp * Eigen::Vector3d::UnitZ().cross(secondary);
    jacobians->kappa = dxdBase * c / (kappa * kappa);
  }
  return intrinsics.project(secondary);
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
