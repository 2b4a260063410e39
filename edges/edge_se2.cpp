#include "lrsvo/edges/edge_se2.h"

#include <Eigen/Geometry>

namespace lrsvo {

template class AutoDiffEdge<EdgeSE2, 3, VertexSE2, VertexSE2>;

namespace {

Eigen::Matrix2d rotation(double angle) { return Eigen::Rotation2Dd(angle).toRotationMatrix(); }

}  // namespace

void EdgeSE2::computeJacobians() {
  const VertexSE2& from = *vertexAs<0>();
  const VertexSE2& to = *vertexAs<1>();
  // Both rotations transposed, applied to world vectors: Rz^T Ri^T.
  const Eigen::Matrix2d toResidual = rotation(measurement_[2] + from.angle()).transpose();
  // d(Ri^T)/dtheta_i = -S Ri^T with S = [0 -1; 1 0], and Rz^T S = S Rz^T.
  Eigen::Matrix2d S;
  S << 0.0, -1.0, 1.0, 0.0;
  const Eigen::Vector2d difference = to.translation() - from.translation();
  jacobian<0>().topLeftCorner<2, 2>() = -toResidual;
  jacobian<0>().topRightCorner<2, 1>() = -S * toResidual * difference;
  jacobian<0>().bottomRows<1>() << 0.0, 0.0, -1.0;
  jacobian<1>().topLeftCorner<2, 2>() = toResidual;
  jacobian<1>().topRightCorner<2, 1>().setZero();
  jacobian<1>().bottomRows<1>() << 0.0, 0.0, 1.0;
}

}  // namespace lrsvo
