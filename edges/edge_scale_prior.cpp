#include "lrsvo/edges/edge_scale_prior.h"

namespace lrsvo {

template class AutoDiffEdge<EdgeScalePrior, 1, VertexScale>;

void EdgeScalePrior::computeJacobians() { jacobian<0>()(0, 0) = 1.0; }

}  // namespace lrsvo
