#include "lrsvo/graph/optimization_algorithm.h"

#include <cmath>
#include <cstdio>

namespace lrsvo {

OptimizationContext::OptimizationContext(BlockSystem& system, LinearSolver& solver, ConstraintHandler& constraints,
                                         const SolverOptions& options, SolverSummary& summary)
    : system_(system),
      solver_(solver),
      constraints_(constraints),
      options_(options),
      summary_(summary),
      solverTimesAtStart_(solver.times()) {}

void OptimizationContext::recordSolverTimes() {
  summary_.schurSeconds = solver_.times().schurSeconds - solverTimesAtStart_.schurSeconds;
  summary_.factorizeSeconds = solver_.times().factorizeSeconds - solverTimesAtStart_.factorizeSeconds;
}

double OptimizationContext::linearize() {
  const Stopwatch start;
  const double cost = system_.fill(options_.threads);
  constraints_.constrainSystem(system_);
  summary_.linearizeSeconds += start.seconds();
  return cost;
}

bool OptimizationContext::solveStep(const Eigen::VectorXd& shift, Eigen::VectorXd& dx) {
  system_.setDiagonalShift(shift);
  const Eigen::VectorXd rhs = -system_.gradient();
  const bool ok = solver_.solve(system_, rhs, dx, options_.threads);
  recordSolverTimes();
  // A step the constraints adjusted, or an iterative solver's, does not solve
  // (H + D) dx = -g exactly.
  stepAdjusted_ = ok && constraints_.adjustStep(system_, dx);
  stepSolvesTheSystem_ = ok && !stepAdjusted_ && solver_.exactSteps();
  return ok;
}

bool OptimizationContext::accelerateStep(const Eigen::VectorXd& shift, double h, double maxRatio, Eigen::VectorXd& dx) {
  if (stepAdjusted_) return true;
  const Stopwatch start;
  const Eigen::VectorXd rhs = -system_.secondDirectionalGradient(dx, h);
  summary_.costSeconds += start.seconds();
  Eigen::VectorXd acceleration;
  const bool ok = solver_.solve(system_, rhs, acceleration, options_.threads);
  recordSolverTimes();
  if (!ok || !acceleration.allFinite()) return false;
  // The damping's metric: diag(H) clamped in multiplicative damping (lambda cancels), plain in additive.
  const double velocity = dx.dot(shift.cwiseProduct(dx));
  const double accelerationNorm = acceleration.dot(shift.cwiseProduct(acceleration));
  if (!(4.0 * accelerationNorm <= maxRatio * maxRatio * velocity)) return false;
  dx += 0.5 * acceleration;
  stepSolvesTheSystem_ = false;
  return true;
}

double OptimizationContext::predictedDecrease(const Eigen::VectorXd& shift, const Eigen::VectorXd& dx) const {
  const double linear = -system_.gradient().dot(dx);
  const double damping = dx.dot(shift.cwiseProduct(dx));
  // A step that solves (H + D) dx = -g has dx^T H dx = -g^T dx - dx^T D dx;
  // any other takes dx^T (H + D) dx - dx^T D dx from the blocks, which hold H + D.
  if (stepSolvesTheSystem_) return 0.5 * (linear + damping);
  return linear - 0.5 * (dx.dot(system_.multiply(dx)) - damping);
}

void OptimizationContext::applyStep(const Eigen::VectorXd& dx) {
  system_.saveEstimates();
  system_.applyStep(dx);
  constraints_.afterStep(system_);
}

double OptimizationContext::cost() {
  const Stopwatch start;
  const double value = system_.cost(options_.threads);
  summary_.costSeconds += start.seconds();
  return value;
}

double OptimizationContext::estimateNorm() const {
  double squared = 0.0;
  std::vector<double> values;
  for (int i = 0; i < system_.blockCount(); ++i) {
    const Vertex* v = system_.vertex(i);
    values.resize(v->estimateSize());
    v->getEstimate(values.data());
    for (double x : values) squared += x * x;
  }
  return std::sqrt(squared);
}

double OptimizationContext::elapsedSeconds() const { return stopwatch_.seconds(); }

void OptimizationContext::record(IterationRecord record) {
  record.cumulativeSeconds = elapsedSeconds();
  record.iterationSeconds = record.cumulativeSeconds - lastRecordSeconds_;
  lastRecordSeconds_ = record.cumulativeSeconds;
  if (options_.verbose)
    std::fprintf(stderr, "%4d cost %.6e change %10.3e |g| %9.2e |dx| %9.2e lambda %9.2e %s %.3fs\n", record.iteration,
                 record.cost, record.costChange, record.gradientMaxNorm, record.stepNorm, record.lambda,
                 record.accepted ? "accepted" : "rejected", record.cumulativeSeconds);
  summary_.iterations.push_back(record);
}

}  // namespace lrsvo
