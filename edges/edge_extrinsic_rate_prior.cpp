#include "lrsvo/edges/edge_extrinsic_rate_prior.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeExtrinsicRatePrior, 6, VertexExtrinsicRate>;

void EdgeExtrinsicRatePrior::computeJacobians() { jacobian<0>().setIdentity(); }

}  // namespace lrsvo
