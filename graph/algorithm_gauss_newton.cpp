#include <cmath>

#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// Gauss-Newton with step halving: the full step is tried first; a step that
// would raise the cost is halved up to kMaxHalvings times, never taken.
class GaussNewton : public OptimizationAlgorithm {
 protected:
  void begin(OptimizationContext& context) override {
    noShift_ = Eigen::VectorXd::Zero(context.system().scalarCount());
  }

  Step tryStep(OptimizationContext& context, double cost, IterationRecord& record, double& trialCost) override {
    constexpr int kMaxHalvings = 10;
    const SolverOptions& options = context.options();
    if (!context.solveStep(noShift_, dx_)) {
      context.summary().termination = Termination::kSingularSystem;
      context.summary().message = "H is not positive definite: is the gauge fixed?";
      return Step::kStop;
    }
    record.stepNorm = dx_.norm();
    if (record.stepNorm <= options.parameterTolerance * (context.estimateNorm() + options.parameterTolerance)) {
      context.record(record);
      context.summary().termination = Termination::kParameterTolerance;
      return Step::kStop;
    }
    for (int halving = 0; halving <= kMaxHalvings; ++halving, dx_ *= 0.5) {
      context.applyStep(dx_);
      trialCost = context.cost();
      if (std::isfinite(trialCost) && trialCost < cost) {
        record.costChange = cost - trialCost;
        return Step::kAccepted;
      }
      context.rejectStep();
    }
    noDescent_ = true;
    return Step::kRejected;
  }

  bool exhausted(SolverSummary& summary) const override {
    if (!noDescent_) return false;
    summary.termination = Termination::kNoDescent;
    return true;
  }

 private:
  Eigen::VectorXd noShift_, dx_;
  bool noDescent_ = false;
};

}  // namespace

void addGaussNewton(Registry<OptimizationAlgorithm>& registry) {
  registry.addType<GaussNewton>("gn", "Gauss-Newton with step halving");
}
}  // namespace lrsvo
