#include <algorithm>
#include <vector>

#include "lrsvo/constraints/builtin_methods.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// Projected (active-set) Levenberg-Marquardt, the paper's proposed future
// work: a parameter on a bound whose gradient points out of the box is held
// (zero step); every other step is projected back into the box. No term
// enters the cost, so steps near a bound are not shortened.
class GradientProjection : public ConstraintMethod {
 public:
  void constrainSystem(BlockSystem& system) override {
    for (const Bounds::Bound& bound : bounds_.all()) {
      const int block = system.blockOf(bound.vertex);
      if (block < 0) continue;
      const double x = Bounds::value(bound);
      const double g = system.gradient()[system.offset(block) + bound.index];
      const double tolerance = 1e-12 * (bound.upper - bound.lower);
      const bool atLower = x <= bound.lower + tolerance && g > 0.0;
      const bool atUpper = x >= bound.upper - tolerance && g < 0.0;
      if (atLower || atUpper) system.holdCoordinate(block, bound.index);
    }
  }

  bool adjustStep(const BlockSystem& system, Eigen::VectorXd& dx) override {
    return limitBoundedSteps(system, dx, [](const Bounds::Bound& bound, double x, double step) {
      return std::clamp(x + step, bound.lower, bound.upper) - x;
    });
  }

  // x + (clamp(x + dx) - x) can miss the bound by rounding: put it on exactly.
  void afterStep(const BlockSystem&) override {
    for (const Bounds::Bound& bound : bounds_.all()) {
      const double x = Bounds::value(bound);
      if (x < bound.lower || x > bound.upper) Bounds::setValue(bound, std::clamp(x, bound.lower, bound.upper));
    }
  }
};

}  // namespace

void addGradientProjection(Registry<ConstraintMethod>& registry) {
  registry.addType<GradientProjection>(
      "gradient_projection",
      "projected active-set Levenberg-Marquardt: hold parameters at active bounds, project steps");
}
}  // namespace lrsvo
