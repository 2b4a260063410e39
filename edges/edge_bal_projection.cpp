#include "lrsvo/edges/edge_bal_projection.h"

#include "lrsvo/vertices/so3.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeBalProjection, 2, VertexBalCamera, VertexPoint3>;

Eigen::Vector3d angleAxisRotate(const Eigen::Vector3d& w, const Eigen::Vector3d& x) {
  return rotateByAngleAxis<double>(w, x);
}

void EdgeBalProjection::computeJacobians() {
  const auto& camera = vertexAs<0>()->estimate();
  const Eigen::Vector3d w = camera.head<3>();
  const Eigen::Matrix3d R = expSO3(w);
  const Eigen::Vector3d RX = R * vertexAs<1>()->estimate();
  const Eigen::Vector3d P = RX + camera.segment<3>(3);
  const double f = camera[6], k1 = camera[7], k2 = camera[8];
  const double iz = 1.0 / P.z();
  const Eigen::Vector2d p = -P.head<2>() * iz;
  const double r2 = p.squaredNorm();
  const double distortion = 1.0 + r2 * (k1 + k2 * r2);

  Eigen::Matrix<double, 2, 3> dp_dP;
  dp_dP << -iz, 0, P.x() * iz * iz, 0, -iz, P.y() * iz * iz;
  // d(f d p)/dp = f (d I + p (dd/dp)), dd/dp = 2 (k1 + 2 k2 r2) p^T
  const Eigen::Matrix2d du_dp =
      f * (distortion * Eigen::Matrix2d::Identity() + 2.0 * (k1 + 2.0 * k2 * r2) * p * p.transpose());
  const Eigen::Matrix<double, 2, 3> du_dP = du_dp * dp_dP;

  auto& jc = jacobian<0>();
  jc.leftCols<3>() = -du_dP * skew(RX) * leftJacobianSO3(w);
  jc.middleCols<3>(3) = du_dP;
  jc.col(6) = distortion * p;
  jc.col(7) = f * r2 * p;
  jc.col(8) = f * r2 * r2 * p;
  jacobian<1>() = du_dP * R;
}

}  // namespace lrsvo
