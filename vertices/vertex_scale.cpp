#include "vertices/vertex_scale.h"

#include "graph/registry.h"

namespace lrsvo {

VertexScale::VertexScale(int id, double kappa) : VectorVertex<1>(id) { estimate_[0] = kappa; }

LRSVO_REGISTER_TYPE(Vertex, VertexScale);

}  // namespace lrsvo
