#include "lrsvo/edges/edge_project_base.h"

#include "lrsvo/vertices/so3.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeProjectBase, 2, VertexPose, VertexPoint3>;

void EdgeProjectBase::computeJacobians() {
  const VertexPose& pose = *vertexAs<0>();
  const Eigen::Vector3d pointInCamera = pose.rotation() * vertexAs<1>()->estimate() + pose.translation();
  const Eigen::Matrix<double, 2, 3> dxdp = intrinsics_.projectJacobian(pointInCamera);
  // pose update X_c <- Exp(dphi) X_c + dt
  jacobian<0>().leftCols<3>() = dxdp;
  jacobian<0>().rightCols<3>() = -dxdp * skew(pointInCamera);
  jacobian<1>() = dxdp * pose.rotation();
}

}  // namespace lrsvo
