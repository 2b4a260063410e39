#include "lrsvo/vertices/vertex_point3.h"

namespace lrsvo {

VertexPoint3::VertexPoint3(int id, const Eigen::Vector3d& position) : VectorVertex<3>(id) {
  estimate_ = position;
  setMarginalized(true);
}

}  // namespace lrsvo
