#pragma once

#include <string>

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/types.h>

#include "apps/bench/bench_common.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo::bench {

// Ceres' Levenberg-Marquardt set up to stop by our rules: tolerances,
// iteration cap, time budget, starting lambda (initial trust region radius
// 1 / lambda) and thread count come from `stopping`. Jacobi scaling on, inner
// iterations off, SuiteSparse for the sparse and Eigen for the dense solvers,
// silent. The caller adds an elimination ordering when it wants one.
ceres::Solver::Options ceresSolverOptions(const SolverOptions& stopping, ceres::LinearSolverType linearSolver);

// The condition that stopped Ceres, named as our SolverSummary names it (Ceres' summary
// message says which tolerance it was); Ceres' own type and message for any other.
std::string ceresTerminationName(const ceres::Solver::Summary& summary);

// Runs ceres::Solve (only that is timed) and reports it in the common form.
// `iterations` counts steps computed, as ours does. Throws lrsvo::Error when
// Ceres rejects the options or fails.
SolveResult solveWithCeres(const ceres::Solver::Options& options, ceres::Problem& problem);

}  // namespace lrsvo::bench
