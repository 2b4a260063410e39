#include "vertices/vertex_extrinsic_rate.h"

#include "graph/registry.h"

namespace lrsvo {

VertexExtrinsicRate::VertexExtrinsicRate(int id, const Vector6& rate) : VectorVertex<6>(id) { estimate_ = rate; }

LRSVO_REGISTER_TYPE(Vertex, VertexExtrinsicRate);

}  // namespace lrsvo
