#include "lrsvo/edges/edge_scale_prior.h"

namespace lrsvo {

void EdgeScalePrior::computeResidual(Residual& residual) const {
  residual[0] = vertexAs<0>()->kappa() - measurement_[0];
}

void EdgeScalePrior::computeJacobians() { jacobian<0>()(0, 0) = 1.0; }

}  // namespace lrsvo
