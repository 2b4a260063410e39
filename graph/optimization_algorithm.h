#pragma once

#include <string>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/constraint_handler.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/solver_options.h"
#include "lrsvo/graph/solver_summary.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

// Everything an algorithm needs for one solve, with the timed operations
// shared by all algorithms.
class OptimizationContext {
 public:
  OptimizationContext(BlockSystem& system, LinearSolver& solver, ConstraintHandler& constraints,
                      const SolverOptions& options, SolverSummary& summary);

  BlockSystem& system() { return system_; }
  const SolverOptions& options() const { return options_; }
  SolverSummary& summary() { return summary_; }
  ConstraintHandler& constraints() { return constraints_; }

  // Fills H and g at the current estimates and applies the constraints.
  double linearize();
  // Solves (H + diag(shift)) dx = -g, then lets the constraints shape dx;
  // false when the system is not positive definite.
  bool solveStep(const Eigen::VectorXd& shift, Eigen::VectorXd& dx);
  // Geodesic acceleration of the step dx of the last solveStep(): solves
  // (H + diag(shift)) a = -sum_e J_e^T r''_e (BlockSystem::secondDirectionalGradient)
  // and sets dx += a / 2. False, dx unchanged, when that system fails or
  // 2 |a| > maxRatio |dx| in the metric diag(shift). A step the constraints
  // shaped is left as it is (true).
  bool accelerateStep(const Eigen::VectorXd& shift, double h, double maxRatio, Eigen::VectorXd& dx);
  // Decrease of the quadratic model, -g^T dx - 1/2 dx^T H dx, for the step
  // of the last solveStep() (or accelerateStep()).
  double predictedDecrease(const Eigen::VectorXd& shift, const Eigen::VectorXd& dx) const;
  // Applies x <- x [+] dx to the active vertices (estimates saved first, so
  // rejectStep() restores them).
  void applyStep(const Eigen::VectorXd& dx);
  void rejectStep() { system_.restoreEstimates(); }
  // Cost at the current estimates.
  double cost();
  // Norm of all active estimates, for the parameter tolerance.
  double estimateNorm() const;
  double elapsedSeconds() const;
  bool outOfTime() const { return elapsedSeconds() >= options_.maxSeconds; }
  // Appends an iteration record (timing filled in) and prints it when verbose.
  void record(IterationRecord record);

 private:
  // The summary's Schur and factorisation times: this solve's share of the solver's totals.
  void recordSolverTimes();

  BlockSystem& system_;
  LinearSolver& solver_;
  ConstraintHandler& constraints_;
  const SolverOptions& options_;
  SolverSummary& summary_;
  const LinearSolverTimes solverTimesAtStart_;  // the solver's totals before this solve (it may be reused)
  Stopwatch stopwatch_;                         // since the context was made
  double lastRecordSeconds_ = 0.0;
  bool stepSolvesTheSystem_ = true;
  bool stepAdjusted_ = false;  // the constraints shaped the last step
};

// The head of a solve's summary, shared by every minimiser (the optimiser's
// algorithms, and constraint methods with loops of their own): the solver's
// name, threads, the system's sizes and its cost at the start.
SolverSummary beginSummary(const std::string& solverName, const Graph& graph, const BlockSystem& system, int threads);

// A minimiser over the block system, registered by name in
// Registry<OptimizationAlgorithm> ("lm", "gn"). Every algorithm shares one
// loop (run): the termination tests (gradient, iterations, time, function
// tolerance), the iteration records, the step counts and the final cost, as
// Ceres' trust-region minimiser is shared by its strategies. An algorithm
// supplies its step: how it is computed, tried, accepted or rejected.
class OptimizationAlgorithm {
 public:
  // The graph library's algorithms (Registry<OptimizationAlgorithm> adds them on first use).
  static void addBuiltins(Registry<OptimizationAlgorithm>& registry);

  virtual ~OptimizationAlgorithm() = default;
  // Runs from the current estimates; fills iterations, final cost, termination.
  void run(OptimizationContext& context);

 protected:
  enum class Step {
    kAccepted,  // the estimates moved to the trial point
    kRejected,  // the estimates are as they were
    kStop,  // the algorithm ends the run: it set the summary's termination (and recorded the iteration if it should)
  };
  // Called once, after the first linearisation.
  virtual void begin(OptimizationContext& context) { (void)context; }
  // Tries one step from the current linearisation, whose cost is `cost`;
  // fills the record's step norm, lambda and cost change, and for an accepted
  // step the trial point's cost.
  virtual Step tryStep(OptimizationContext& context, double cost, IterationRecord& record, double& trialCost) = 0;
  // After a rejected step, before its record is written.
  virtual void afterRejection() {}
  // True when the algorithm cannot go on (it then sets the termination); asked after every step.
  virtual bool exhausted(SolverSummary& summary) const {
    (void)summary;
    return false;
  }
};

}  // namespace lrsvo
