#include "lrsvo/vertices/vertex_extrinsic_rate.h"

namespace lrsvo {

VertexExtrinsicRate::VertexExtrinsicRate(int id, const Vector6& rate) : VectorVertex<6>(id) { estimate_ = rate; }

}  // namespace lrsvo
