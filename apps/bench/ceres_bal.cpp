#include "apps/bench/ceres_bal.h"

#include <memory>
#include <optional>
#include <utility>

#include <ceres/autodiff_cost_function.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/rotation.h>
#include <ceres/solver.h>
#include <ceres/version.h>

#include "apps/bench/ceres_solve.h"
#include "lrsvo/graph/error.h"

namespace lrsvo::bench {

namespace {

// The BAL (Snavely) reprojection residual, the same model as
// edges/edge_bal_projection.cpp: camera = (angle-axis w, t, f, k1, k2),
// P = R(w) X + t, p = -P / P_z, residual = f (1 + k1 |p|^2 + k2 |p|^4) p - observed.
class SnavelyResidual {
 public:
  explicit SnavelyResidual(const Eigen::Vector2d& observed) : observed_(observed) {}

  template <typename T>
  bool operator()(const T* camera, const T* point, T* residual) const {
    T P[3];
    ceres::AngleAxisRotatePoint(camera, point, P);
    for (int i = 0; i < 3; ++i) P[i] += camera[3 + i];
    const T px = -P[0] / P[2];
    const T py = -P[1] / P[2];
    const T r2 = px * px + py * py;
    const T distortion = 1.0 + r2 * (camera[7] + camera[8] * r2);
    residual[0] = camera[6] * distortion * px - observed_.x();
    residual[1] = camera[6] * distortion * py - observed_.y();
    return true;
  }

  static ceres::CostFunction* create(const Eigen::Vector2d& observed) {
    return new ceres::AutoDiffCostFunction<SnavelyResidual, 2, 9, 3>(new SnavelyResidual(observed));
  }

 private:
  Eigen::Vector2d observed_;
};

}  // namespace

SolveResult solveBalWithCeres(BalProblem& problem, const SolverOptions& stopping,
                              ceres::LinearSolverType linearSolver) {
  ceres::Problem ceresProblem;
  for (const BalObservation& observation : problem.observations)
    ceresProblem.AddResidualBlock(SnavelyResidual::create(observation.pixel), nullptr,
                                  problem.cameras[observation.camera].data(), problem.points[observation.point].data());

  ceres::Solver::Options options = ceresSolverOptions(stopping, linearSolver);
  // ITERATIVE_SCHUR with the preconditioner ours uses (Ceres' default is JACOBI).
  if (linearSolver == ceres::ITERATIVE_SCHUR) options.preconditioner_type = ceres::SCHUR_JACOBI;
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  for (auto& point : problem.points)
    if (ceresProblem.HasParameterBlock(point.data())) ordering->AddElementToGroup(point.data(), 0);
  for (auto& camera : problem.cameras)
    if (ceresProblem.HasParameterBlock(camera.data())) ordering->AddElementToGroup(camera.data(), 1);
  options.linear_solver_ordering = ordering;

  std::string invalid;
  if (!options.IsValid(&invalid)) throw Error("bench: Ceres rejects the solver options: " + invalid);

  ceres::Solver::Summary summary;
  const SolveMemory memory;
  const Stopwatch stopwatch;
  ceres::Solve(options, &ceresProblem, &summary);
  const double seconds = stopwatch.seconds();
  const double cpuSeconds = stopwatch.cpuSeconds();
  const std::optional<double> megabytes = memory.addedMegabytes();
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
  result.solveMegabytes = megabytes;
  return result;
}

std::string ceresConfiguration() {
  return std::string("Ceres ") + CERES_VERSION_STRING +
         ": AutoDiff Jacobians of the Snavely model (same projection as edges/edge_bal_projection.cpp), "
         "LEVENBERG_MARQUARDT, jacobi_scaling on, inner iterations off, points eliminated first, "
         "sparse library SUITE_SPARSE, dense library EIGEN, ITERATIVE_SCHUR preconditioned by SCHUR_JACOBI "
         "(eta 0.1, at most 500 iterations: Ceres' defaults)";
}

}  // namespace lrsvo::bench
