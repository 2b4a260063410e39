#include <algorithm>
#include <cmath>

#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// Levenberg-Marquardt with Nielsen's lambda update (as Ceres' trust region):
// a step is taken only when it lowers the cost by a relative gain above
// LevenbergMarquardtOptions::minRelativeDecrease; otherwise the estimates are
// restored and lambda grows geometrically.
class LevenbergMarquardt : public OptimizationAlgorithm {
 public:
  void run(OptimizationContext& context) override {
    const SolverOptions& options = context.options();
    const LevenbergMarquardtOptions& lm = options.lm;
    SolverSummary& summary = context.summary();
    BlockSystem& system = context.system();
    const bool multiplicative = lm.damping == Damping::kMultiplicative;

    double cost = context.linearize();
    double lambda = lm.initialLambda;
    if (lambda < 0) lambda = multiplicative ? 1e-4 : 1e-4 * system.diagonal().maxCoeff();
    double growth = 2.0;
    summary.iterations.front().gradientMaxNorm = context.constraints().gradientMaxNorm(system);
    Eigen::VectorXd dx, shift(system.scalarCount());

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

      for (int i = 0; i < shift.size(); ++i)
        shift[i] = multiplicative ? lambda * std::clamp(system.diagonal()[i], lm.minDiagonal, lm.maxDiagonal) : lambda;
      IterationRecord record{.iteration = iteration, .cost = cost, .gradientMaxNorm = gradientNorm, .lambda = lambda};

      bool accepted = false;
      if (context.solveStep(shift, dx)) {
        record.stepNorm = dx.norm();
        const double xNorm = context.estimateNorm();
        if (record.stepNorm <= options.parameterTolerance * (xNorm + options.parameterTolerance)) {
          context.record(record);
          summary.termination = Termination::kParameterTolerance;
          break;
        }
        const double predicted = context.predictedDecrease(shift, dx);
        context.applyStep(dx);
        const double trialCost = context.cost();
        const double decrease = cost - trialCost;
        record.costChange = decrease;
        const double gain = decrease / predicted;
        accepted = std::isfinite(trialCost) && decrease > 0 && predicted > 0 && gain > lm.minRelativeDecrease;
        if (accepted) {
          const double relativeDecrease = decrease / cost;
          cost = trialCost;
          record.cost = cost;
          record.accepted = true;
          ++summary.successfulSteps;
          lambda = std::max(lm.minLambda, lambda * std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3)));
          growth = 2.0;
          if (relativeDecrease <= options.functionTolerance) {
            context.record(record);
            summary.termination = Termination::kFunctionTolerance;
            break;
          }
          cost = context.linearize();
        } else {
          context.rejectStep();
        }
      }
      if (!accepted) {
        ++summary.unsuccessfulSteps;
        lambda *= growth;
        growth *= 2.0;
      }
      context.record(record);
      if (lambda > lm.maxLambda) {
        summary.termination = Termination::kDampingLimit;
        break;
      }
    }
    summary.finalCost = cost;
  }
};

}  // namespace

void addLevenbergMarquardt(Registry<OptimizationAlgorithm>& registry) {
  registry.addType<LevenbergMarquardt>("lm", "Levenberg-Marquardt, multiplicative or additive damping");
}
}  // namespace lrsvo
