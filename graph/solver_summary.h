#pragma once

#include <string>
#include <vector>

namespace lrsvo {

// Why a solve stopped.
enum class Termination {
  kFunctionTolerance,
  kGradientTolerance,
  kParameterTolerance,
  kMaxIterations,
  kTimeLimit,
  kDampingLimit,    // lambda grew past its cap: no step lowers the cost
  kNoDescent,       // Gauss-Newton: even short steps raise the cost
  kSingularSystem,  // the normal equations are not positive definite (Gauss-Newton)
  kNonFiniteCost,   // a step produced NaN/inf and could not be recovered
};

const char* terminationName(Termination termination);
bool isConvergence(Termination termination);

struct IterationRecord {
  int iteration = 0;
  double cost = 0.0;        // after the iteration (unchanged when rejected)
  double costChange = 0.0;  // actual decrease of the trial step
  double gradientMaxNorm = 0.0;
  double stepNorm = 0.0;
  double lambda = 0.0;
  bool accepted = false;
  double iterationSeconds = 0.0;
  double cumulativeSeconds = 0.0;
};

// What one solve did, Ceres style. Costs are 1/2 sum rho(||r||^2).
struct SolverSummary {
  std::string solver;
  int vertexCount = 0;  // active (non-fixed) vertices
  int edgeCount = 0;
  int parameterCount = 0;  // scalar unknowns
  int threads = 1;
  double initialCost = 0.0;
  double finalCost = 0.0;
  std::vector<IterationRecord> iterations;  // [0] is the start
  int successfulSteps = 0;
  int unsuccessfulSteps = 0;
  Termination termination = Termination::kMaxIterations;
  std::string message;
  double setupSeconds = 0.0;  // structure, ordering, symbolic analysis
  // The block structure and symbolic analysis came from the optimizer's
  // previous solve of the same structure (setupSeconds is then only the check).
  bool structureReused = false;
  double linearizeSeconds = 0.0;  // residuals, Jacobians and block sums
  double schurSeconds = 0.0;
  double factorizeSeconds = 0.0;
  double costSeconds = 0.0;  // evaluating trial steps
  double totalSeconds = 0.0;
  // The direct linear solver's fill-reducing ordering and the flops of one
  // factorisation (LinearSolver::factorization); empty and 0 for iterative ones.
  std::string ordering;
  double factorizationFlops = 0.0;

  int iterationCount() const { return static_cast<int>(iterations.size()) - 1; }
  bool converged() const { return isConvergence(termination); }
  std::string briefReport() const;
  std::string fullReport() const;
  // One JSON object with initial_cost, final_cost, iterations, total_time_s,
  // termination, the phase times and the per-iteration records.
  std::string toJson() const;
};

}  // namespace lrsvo
