#include "lrsvo/vertices/vertex_types.h"

#include <string>
#include <utility>

#include "lrsvo/graph/registry.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "lrsvo/vertices/vertex_extrinsic_rate.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_scale.h"
#include "lrsvo/vertices/vertex_se2.h"
#include "lrsvo/vertices/vertex_se3_quat.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"
#include "lrsvo/vertices/vertex_vector.h"

namespace lrsvo {
namespace {

template <int... N>
void addVectorTypes(std::integer_sequence<int, N...>) {
  (Registry<Vertex>::instance().addType<VertexVector<N + 1>>(VertexVector<N + 1>::kTypeTag,
                                                             "VertexVector<" + std::to_string(N + 1) + ">"),
   ...);
}

}  // namespace

void registerVertexTypes() {
  static const bool registered = [] {
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexBalCamera);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexExtrinsicRate);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexPoint3);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexPose);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexScale);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexSE2);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexSE3Quat);
    LRSVO_ADD_TYPE(Registry<Vertex>::instance(), VertexStereoExtrinsic);
    addVectorTypes(std::make_integer_sequence<int, 9>{});
    return true;
  }();
  (void)registered;
}

}  // namespace lrsvo
