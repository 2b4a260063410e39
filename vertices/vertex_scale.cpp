#include "lrsvo/vertices/vertex_scale.h"

namespace lrsvo {

VertexScale::VertexScale(int id, double kappa) : VectorVertex<1>(id) { estimate_[0] = kappa; }

}  // namespace lrsvo
