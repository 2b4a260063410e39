#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/frontend/datasets/nist_problem.h"
#include "lrsvo/graph/numeric_diff.h"
#include "lrsvo/graph/solver_options.h"
#include "lrsvo/graph/solver_summary.h"

namespace lrsvo {

// The settings of the NIST runs: LM on the dense normal equations with every
// tolerance at machine epsilon and 1000 iterations, as the solvers that report
// on NIST run them.
SolverOptions nistSolverOptions();

// How the regression's edges get their Jacobians.
enum class RegressionJacobians { kAutoDiff, kNumeric };

struct NistSolveOptions {
  SolverOptions solver = nistSolverOptions();
  RegressionJacobians jacobians = RegressionJacobians::kAutoDiff;
  // With kNumeric: steps relative to each parameter however small (a
  // regression's parameters span 6e-9 to 6e3 and its residuals follow each).
  NumericDiffOptions numeric{.typicalMagnitude = 0.0};
};

// One solve of a NIST problem from one of its starts.
struct NistSolve {
  std::string problem;
  int start = 1;  // 1 or 2
  Eigen::VectorXd estimate;
  // Correct significant digits per parameter, the log relative error
  // -log10(|b - c| / |c|) against the certified c, capped at 11 (the
  // certified values' own digits); 0 when the estimate is not finite.
  Eigen::VectorXd digits;
  double residualSumOfSquares = 0.0;
  SolverSummary summary;

  double minDigits() const { return digits.minCoeff(); }
  // The usual criterion: every parameter to at least 4 digits.
  bool solved() const { return minDigits() >= 4.0; }
};

// Log relative error of an estimate against a certified value, capped at 11.
double correctDigits(double estimate, double certified);
// The same per parameter.
Eigen::VectorXd correctDigits(const Eigen::VectorXd& estimate, const Eigen::VectorXd& certified);

// The NIST problem files (*.dat) of a folder, sorted by name; throws
// lrsvo::Error when the folder cannot be read or holds none.
std::vector<std::string> nistProblemFiles(const std::string& directory);

// Builds the regression as a graph (one parameter vertex, one edge per
// observation, r_i = y_i - f(b; x_i)) and solves it from start 1 or 2.
NistSolve solveNist(const NistProblem& problem, int start, const NistSolveOptions& options);

}  // namespace lrsvo
