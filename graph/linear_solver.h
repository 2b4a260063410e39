#pragma once

#include <string>

#include <Eigen/Core>

#include "lrsvo/graph/block_system.h"

namespace lrsvo {

// Seconds spent in a linear solver's phases, summed over its solves.
struct LinearSolverTimes {
  double schurSeconds = 0.0;      // eliminating marginalised blocks and back-substitution
  double factorizeSeconds = 0.0;  // factorising and solving the (reduced) system
};

// How a direct solver factorises its (reduced) system, after analyze().
struct FactorizationInfo {
  std::string ordering;  // fill-reducing ordering: "amd", "metis", "nesdis", "dense"; empty for iterative solvers
  double flops = 0.0;    // of one factorisation, as the back end counts them; 0 when unknown
};

template <typename Product>
class Registry;

// Solves H x = rhs for the block system. Registered by name in
// Registry<LinearSolver>: "dense", "cholmod", "schur_dense", "schur_cholmod",
// and the iterative "schur_pcg" and "schur_power_series".
class LinearSolver {
 public:
  // The graph library's linear solvers (Registry<LinearSolver> adds them on first use).
  static void addBuiltins(Registry<LinearSolver>& registry);

  virtual ~LinearSolver() = default;
  // True when the solver eliminates marginalised vertices (needs them ordered last).
  virtual bool usesSchurOrdering() const = 0;
  // Prepares for systems of this structure (symbolic analysis); once per structure.
  virtual void analyze(const BlockSystem& system) = 0;
  // Returns false when H is not positive definite (x is then undefined).
  virtual bool solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) = 0;
  // False for iterative solvers, whose steps solve H x = rhs only to their
  // tolerance (the optimiser then predicts a step's decrease from H itself).
  virtual bool exactSteps() const { return true; }
  virtual FactorizationInfo factorization() const { return {}; }

  const LinearSolverTimes& times() const { return times_; }

 protected:
  LinearSolverTimes times_;
};

}  // namespace lrsvo
