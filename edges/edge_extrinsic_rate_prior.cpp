#include "lrsvo/edges/edge_extrinsic_rate_prior.h"

namespace lrsvo {

void EdgeExtrinsicRatePrior::computeJacobians() { jacobian<0>().setIdentity(); }

}  // namespace lrsvo
