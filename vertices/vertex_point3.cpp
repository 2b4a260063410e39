#include "vertices/vertex_point3.h"

#include "graph/registry.h"

namespace lrsvo {

VertexPoint3::VertexPoint3(int id, const Eigen::Vector3d& position) : VectorVertex<3>(id) {
  estimate_ = position;
  setMarginalized(true);
}

LRSVO_REGISTER_TYPE(Vertex, VertexPoint3);

}  // namespace lrsvo
