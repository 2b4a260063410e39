#include "lrsvo/constraints/constraint_types.h"

#include "lrsvo/constraints/barrier_edge.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

void registerConstraintTypes() {
  static const bool registered = [] {
    LRSVO_ADD_TYPE(Registry<Edge>::instance(), BarrierEdge);
    return true;
  }();
  (void)registered;
}

}  // namespace lrsvo
