#include "lrsvo/constraints/builtin_methods.h"

namespace lrsvo {

void ConstraintMethod::addBuiltins(Registry<ConstraintMethod>& registry) {
  addNoConstraints(registry);
  addLogBarrier(registry);
  addGradientProjection(registry);
  addNloptMethods(registry);
}

}  // namespace lrsvo
