#include "constraints/constraint_method.h"
#include "graph/registry.h"

namespace lrsvo {
namespace {

// Ignores the bounds: the unconstrained solve, for comparison.
class NoConstraints : public ConstraintMethod {
 public:
  void begin(Graph&) override {}
};

LRSVO_REGISTER(ConstraintMethod, NoConstraints, "none", "bounds ignored: the unconstrained problem");

}  // namespace
}  // namespace lrsvo
