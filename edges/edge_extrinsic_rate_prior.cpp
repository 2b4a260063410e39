#include "edges/edge_extrinsic_rate_prior.h"

#include "graph/registry.h"

namespace lrsvo {

void EdgeExtrinsicRatePrior::computeResidual(Residual& residual) const {
  residual = vertexAs<0>()->estimate() - measurement_;
}

void EdgeExtrinsicRatePrior::computeJacobians() { jacobian<0>().setIdentity(); }

LRSVO_REGISTER_TYPE(Edge, EdgeExtrinsicRatePrior);

}  // namespace lrsvo
