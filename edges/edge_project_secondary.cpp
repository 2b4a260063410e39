#include "lrsvo/edges/edge_project_secondary.h"

namespace lrsvo {

void EdgeProjectSecondary::computeResidual(Residual& residual) const {
  residual =
      projectSecondary(*vertexAs<0>(), vertexAs<1>()->estimate(), *vertexAs<2>(), 1.0, camera_.intrinsics, nullptr) -
      measurement_;
}

void EdgeProjectSecondary::computeJacobians() {
  SecondaryProjectionJacobians j;
  projectSecondary(*vertexAs<0>(), vertexAs<1>()->estimate(), *vertexAs<2>(), 1.0, camera_.intrinsics, &j);
  jacobian<0>() = j.pose;
  jacobian<1>() = j.point;
  jacobian<2>() = j.extrinsic;
}

void EdgeProjectSecondaryScaled::computeResidual(Residual& residual) const {
  residual = projectSecondary(*vertexAs<0>(), vertexAs<1>()->estimate(), *vertexAs<2>(), vertexAs<3>()->kappa(),
                              camera_.intrinsics, nullptr) -
             measurement_;
}

void EdgeProjectSecondaryScaled::computeJacobians() {
  SecondaryProjectionJacobians j;
  projectSecondary(*vertexAs<0>(), vertexAs<1>()->estimate(), *vertexAs<2>(), vertexAs<3>()->kappa(),
                   camera_.intrinsics, &j);
  jacobian<0>() = j.pose;
  jacobian<1>() = j.point;
  jacobian<2>() = j.extrinsic;
  jacobian<3>() = j.kappa;
}

}  // namespace lrsvo
