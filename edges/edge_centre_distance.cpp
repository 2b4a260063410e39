#include "lrsvo/edges/edge_centre_distance.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeCentreDistance, 1, VertexPose, VertexPose>;

void EdgeCentreDistance::computeJacobians() {
  // Under VertexPose's update the centre C = -R^T t moves by -R^T dt and not
  // at all with the rotation: C' = -R^T Exp(-dphi) (Exp(dphi) t + dt).
  const Eigen::Vector3d difference = vertexAs<1>()->centre() - vertexAs<0>()->centre();
  const Eigen::RowVector3d direction = difference.transpose() / difference.norm();
  jacobian<0>().leftCols<3>() = direction * vertexAs<0>()->rotation().transpose();
  jacobian<0>().rightCols<3>().setZero();
  jacobian<1>().leftCols<3>() = -direction * vertexAs<1>()->rotation().transpose();
  jacobian<1>().rightCols<3>().setZero();
}

}  // namespace lrsvo
