#include "vertices/vertex_bal_camera.h"

#include "graph/registry.h"

namespace lrsvo {
LRSVO_REGISTER_TYPE(Vertex, VertexBalCamera);
}  // namespace lrsvo
