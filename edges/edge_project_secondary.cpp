#include "lrsvo/edges/edge_project_secondary.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeProjectSecondary, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic>;
template class AutoDiffEdge<EdgeProjectSecondaryScaled, 2, VertexPose, VertexPoint3, VertexStereoExtrinsic,
                            VertexScale>;

void EdgeProjectSecondary::computeJacobians() {
  const SecondaryProjectionJacobians j =
      secondaryProjectionJacobians(*vertexAs<0>(), vertexAs<1>()->estimate(), *vertexAs<2>(), 1.0, camera_.intrinsics);
  jacobian<0>() = j.pose;
  jacobian<1>() = j.point;
  jacobian<2>() = j.extrinsic;
}

void EdgeProjectSecondaryScaled::computeJacobians() {
  const SecondaryProjectionJacobians j = secondaryProjectionJacobians(
      *vertexAs<0>(), vertexAs<1>()->estimate(), *vertexAs<2>(), vertexAs<3>()->kappa(), camera_.intrinsics);
  jacobian<0>() = j.pose;
  jacobian<1>() = j.point;
  jacobian<2>() = j.extrinsic;
  jacobian<3>() = j.kappa;
}

}  // namespace lrsvo
