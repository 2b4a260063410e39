#include "lrsvo/edges/edge_types.h"

#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/edges/edge_centre_distance.h"
#include "lrsvo/edges/edge_extrinsic_rate_prior.h"
#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_held_view.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/edges/edge_project_secondary_drifting.h"
#include "lrsvo/edges/edge_scale_prior.h"
#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/vertices/vertex_types.h"

namespace lrsvo {

void registerEdgeTypes() {
  static const bool registered = [] {
    registerVertexTypes();
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeBalProjection);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeCentreDistance);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeExtrinsicRatePrior);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeProjectBase);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeProjectHeldView);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeProjectSecondary);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeProjectSecondaryScaled);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeProjectSecondaryDrifting);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeScalePrior);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeSE2);
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), EdgeSE3Quat);
    return true;
  }();
  (void)registered;
}

}  // namespace lrsvo
