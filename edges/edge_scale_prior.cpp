#include "lrsvo/edges/edge_scale_prior.h"

namespace lrsvo {

void EdgeScalePrior::computeJacobians() { jacobian<0>()(0, 0) = 1.0; }

}  // namespace lrsvo
