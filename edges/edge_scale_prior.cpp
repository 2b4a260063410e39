#include "edges/edge_scale_prior.h"

#include "graph/registry.h"

namespace lrsvo {

void EdgeScalePrior::computeResidual(Residual& residual) const {
  residual[0] = vertexAs<0>()->kappa() - measurement_[0];
}

void EdgeScalePrior::computeJacobians() { jacobian<0>()(0, 0) = 1.0; }

LRSVO_REGISTER_TYPE(Edge, EdgeScalePrior);

}  // namespace lrsvo
