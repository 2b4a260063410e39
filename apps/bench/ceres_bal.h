#pragma once

#include <string>

#include <ceres/types.h>

#include "apps/bench/bench_common.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo::bench {

// Solves the BAL problem in place with Ceres, set up as a Ceres user would:
// one AutoDiff residual per observation with the projection of
// EdgeBalProjection (p = -P / P_z, f (1 + k1 |p|^2 + k2 |p|^4) p - observed),
// points in elimination group 0 and cameras in group 1, Levenberg-Marquardt
// with Jacobi scaling and no inner iterations. Tolerances, iteration cap,
// time budget, starting lambda and thread count come from `stopping`, so both
// libraries stop by the same rules. Only ceres::Solve is timed.
SolveResult solveBalWithCeres(BalProblem& problem, const SolverOptions& stopping, ceres::LinearSolverType linearSolver);

// One line naming the Ceres version and the configuration used above.
std::string ceresConfiguration();

}  // namespace lrsvo::bench
