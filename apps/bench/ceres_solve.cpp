#include "apps/bench/ceres_solve.h"

#include <cmath>
#include <string>
#include <utility>

#include "lrsvo/graph/error.h"

namespace lrsvo::bench {

std::string ceresTerminationName(const ceres::Solver::Summary& summary) {
  const std::pair<const char*, const char*> names[] = {
      {"Function tolerance", "function_tolerance"},   {"Gradient tolerance", "gradient_tolerance"},
      {"Parameter tolerance", "parameter_tolerance"}, {"Maximum number of iterations", "max_iterations"},
      {"Maximum solver time", "time_limit"},          {"Minimum trust region radius", "damping_limit"},
  };
  for (const auto& [prefix, name] : names)
    if (summary.message.rfind(prefix, 0) == 0) return name;
  return ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
}

ceres::Solver::Options ceresSolverOptions(const SolverOptions& stopping, ceres::LinearSolverType linearSolver) {
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = linearSolver;
  options.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  options.dense_linear_algebra_library_type = ceres::EIGEN;  // Ceres' default
  options.use_inner_iterations = false;
  options.jacobi_scaling = true;
  options.initial_trust_region_radius = 1.0 / (stopping.lm.initialLambda > 0 ? stopping.lm.initialLambda : 1e-4);
  options.function_tolerance = stopping.functionTolerance;
  options.gradient_tolerance = stopping.gradientTolerance;
  options.parameter_tolerance = stopping.parameterTolerance;
  options.max_num_iterations = stopping.maxIterations;
  if (std::isfinite(stopping.maxSeconds)) options.max_solver_time_in_seconds = stopping.maxSeconds;
  options.num_threads = stopping.threads;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  return options;
}

SolveResult solveWithCeres(const ceres::Solver::Options& options, ceres::Problem& problem) {
  std::string invalid;
  if (!options.IsValid(&invalid)) throw Error("bench: Ceres rejects the solver options: " + invalid);
  ceres::Solver::Summary summary;
  const Stopwatch stopwatch;
  ceres::Solve(options, &problem, &summary);
  const double seconds = stopwatch.seconds();
  const double cpuSeconds = stopwatch.cpuSeconds();
  if (summary.termination_type == ceres::FAILURE || summary.iterations.empty())
    throw Error("bench: Ceres failed: " + summary.message);

  SolveResult result;
  result.termination = ceresTerminationName(summary);
  // Steps computed, as ours counts them. summary.iterations starts with the
  // start point and leaves out the last step when a function or parameter
  // tolerance stops the solve: Ceres computes and evaluates that step, then
  // discards it (ours records it and keeps it when it lowers the cost).
  const bool stoppedOnStep = result.termination == "function_tolerance" || result.termination == "parameter_tolerance";
  result.iterations = static_cast<int>(summary.iterations.size()) - 1 + (stoppedOnStep ? 1 : 0);
  result.initialCost = summary.initial_cost;
  result.finalCost = summary.final_cost;
  result.totalSeconds = seconds;
  result.cpuSeconds = cpuSeconds;
  result.setupSeconds = summary.preprocessor_time_in_seconds;
  result.linearizeSeconds = summary.jacobian_evaluation_time_in_seconds;
  result.linearSolveSeconds = summary.linear_solver_time_in_seconds;
  result.costSeconds = summary.residual_evaluation_time_in_seconds;
  return result;
}

}  // namespace lrsvo::bench
