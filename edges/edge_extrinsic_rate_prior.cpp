#include "lrsvo/edges/edge_extrinsic_rate_prior.h"

namespace lrsvo {

void EdgeExtrinsicRatePrior::computeResidual(Residual& residual) const {
  residual = vertexAs<0>()->estimate() - measurement_;
}

void EdgeExtrinsicRatePrior::computeJacobians() { jacobian<0>().setIdentity(); }

}  // namespace lrsvo
