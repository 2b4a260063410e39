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
// restored and lambda grows geometrically. With geodesic acceleration a step
// whose second-order correction is too large counts as rejected.
class LevenbergMarquardt : public OptimizationAlgorithm {
 protected:
  void begin(OptimizationContext& context) override {
    const LevenbergMarquardtOptions& lm = context.options().lm;
    multiplicative_ = lm.damping == Damping::kMultiplicative;
    lambda_ = lm.initialLambda;
    if (lambda_ < 0) lambda_ = multiplicative_ ? 1e-4 : 1e-4 * context.system().diagonal().maxCoeff();
    growth_ = 2.0;
    maxLambda_ = lm.maxLambda;
    shift_.resize(context.system().scalarCount());
    // The units the diagonal is clamped in: 1 (the parameters' own), or the
    // squared inverse of Ceres' Jacobi scaling 1 / (1 + |column|) at the start.
    const Eigen::VectorXd& diagonal = context.system().diagonal();
    diagonalUnit_ = Eigen::VectorXd::Ones(diagonal.size());
    if (lm.jacobiScaledDiagonal) diagonalUnit_ = (1.0 + diagonal.array().sqrt()).square().matrix();
  }

  Step tryStep(OptimizationContext& context, double cost, IterationRecord& record, double& trialCost) override {
    const SolverOptions& options = context.options();
    const LevenbergMarquardtOptions& lm = options.lm;
    const BlockSystem& system = context.system();
    for (int i = 0; i < shift_.size(); ++i) {
      const double unit = diagonalUnit_[i];
      shift_[i] = multiplicative_
                      ? lambda_ * unit * std::clamp(system.diagonal()[i] / unit, lm.minDiagonal, lm.maxDiagonal)
                      : lambda_;
    }
    record.lambda = lambda_;
    if (!context.solveStep(shift_, dx_)) return Step::kRejected;

    record.stepNorm = dx_.norm();
    const double xNorm = context.estimateNorm();
    if (record.stepNorm <= options.parameterTolerance * (xNorm + options.parameterTolerance)) {
      context.record(record);
      context.summary().termination = Termination::kParameterTolerance;
      return Step::kStop;
    }
    if (lm.geodesicAcceleration && !context.accelerateStep(shift_, lm.geodesicStep, lm.maxAccelerationRatio, dx_))
      return Step::kRejected;
    const double predicted = context.predictedDecrease(shift_, dx_);
    context.applyStep(dx_);
    trialCost = context.cost();
    const double decrease = cost - trialCost;
    record.costChange = decrease;
    const double gain = decrease / predicted;
    if (!(std::isfinite(trialCost) && decrease > 0 && predicted > 0 && gain > lm.minRelativeDecrease)) {
      context.rejectStep();
      return Step::kRejected;
    }
    lambda_ = std::max(lm.minLambda, lambda_ * std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3)));
    growth_ = 2.0;
    return Step::kAccepted;
  }

  void afterRejection() override {
    lambda_ *= growth_;
    growth_ *= 2.0;
  }

  bool exhausted(SolverSummary& summary) const override {
    if (lambda_ <= maxLambda_) return false;
    summary.termination = Termination::kDampingLimit;
    return true;
  }

 private:
  bool multiplicative_ = true;
  double lambda_ = 0.0;
  double growth_ = 2.0;
  double maxLambda_ = 0.0;
  Eigen::VectorXd diagonalUnit_;  // per scalar, see begin()
  Eigen::VectorXd shift_, dx_;
};

}  // namespace

void addLevenbergMarquardt(Registry<OptimizationAlgorithm>& registry) {
  registry.addType<LevenbergMarquardt>("lm", "Levenberg-Marquardt, multiplicative or additive damping");
}
}  // namespace lrsvo
