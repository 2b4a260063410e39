#include "lrsvo/constraints/builtin_methods.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// Ignores the bounds: the unconstrained solve, for comparison.
class NoConstraints : public ConstraintMethod {
 public:
  void begin(Graph&) override {}
};

}  // namespace

void addNoConstraints(Registry<ConstraintMethod>& registry) {
  registry.addType<NoConstraints>("none", "bounds ignored: the unconstrained problem");
}
}  // namespace lrsvo
