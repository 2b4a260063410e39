#include "lrsvo/vertices/vertex_types.h"

#include "lrsvo/graph/registry.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "lrsvo/vertices/vertex_extrinsic_rate.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_scale.h"
#include "lrsvo/vertices/vertex_se2.h"
#include "lrsvo/vertices/vertex_se3_quat.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

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
    return true;
  }();
  (void)registered;
}

}  // namespace lrsvo
