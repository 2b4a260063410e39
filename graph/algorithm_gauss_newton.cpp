#include <cmath>

#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// Gauss-Newton with step halving: the full step is tried first; a step that
// would raise the cost is halved up to kMaxHalvings times, never taken.
class GaussNewton : public OptimizationAlgorithm {
 public:
  void run(OptimizationContext& context) override {
    constexpr int kMaxHalvings = 10;
    const SolverOptions& options = context.options();
    SolverSummary& summary = context.summary();
    BlockSystem& system = context.system();

    double cost = context.linearize();
    const Eigen::VectorXd noShift = Eigen::VectorXd::Zero(system.scalarCount());
    summary.iterations.front().gradientMaxNorm = context.constraints().gradientMaxNorm(system);
    Eigen::VectorXd dx;

    for (int iteration = 1;; ++iteration) {
      const double gradientNorm = context.constraints().gradientMaxNorm(system);
      if (gradientNorm <= options.gradientTolerance) {
        summary.termination = Termination::kGradientTolerance;
        break;
      }
      if (iteration > options.maxIterations) {
        summary.termination = Termination::kMaxIterations;
        break;
      }
      if (context.outOfTime()) {
        summary.termination = Termination::kTimeLimit;
        break;
      }
      if (!context.solveStep(noShift, dx)) {
        summary.termination = Termination::kSingularSystem;
        summary.message = "H is not positive definite: is the gauge fixed?";
        break;
      }
      IterationRecord record{.iteration = iteration, .cost = cost, .gradientMaxNorm = gradientNorm};
      record.stepNorm = dx.norm();
      if (record.stepNorm <= options.parameterTolerance * (context.estimateNorm() + options.parameterTolerance)) {
        context.record(record);
        summary.termination = Termination::kParameterTolerance;
        break;
      }
      double trialCost = cost;
      for (int halving = 0; halving <= kMaxHalvings; ++halving, dx *= 0.5) {
        context.applyStep(dx);
        trialCost = context.cost();
        if (std::isfinite(trialCost) && trialCost < cost) break;
        context.rejectStep();
      }
      if (!(std::isfinite(trialCost) && trialCost < cost)) {
        ++summary.unsuccessfulSteps;
        context.record(record);
        summary.termination = Termination::kNoDescent;
        break;
      }
      record.costChange = cost - trialCost;
      record.cost = trialCost;
      record.accepted = true;
      ++summary.successfulSteps;
      context.record(record);
      if (record.costChange / cost <= options.functionTolerance) {
        cost = trialCost;
        summary.termination = Termination::kFunctionTolerance;
        break;
      }
      cost = context.linearize();
    }
    summary.finalCost = cost;
  }
};

}  // namespace

void addGaussNewton(Registry<OptimizationAlgorithm>& registry) {
  registry.addType<GaussNewton>("gn", "Gauss-Newton with step halving");
}
}  // namespace lrsvo
