#pragma once

#include <Eigen/Core>

#include "apps/bench/bench_common.h"
#include "lrsvo/frontend/datasets/nist_problem.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo::bench {

struct CeresNistSolve {
  Eigen::VectorXd estimate;
  SolveResult result;
};

// A NIST problem solved by Ceres from start 1 or 2: the same residuals
// (eval/nist_models.h, differentiated by Ceres' Jets), Levenberg-Marquardt
// with DENSE_QR as Ceres' own NIST example runs it, stopping by `stopping`'s
// tolerances and iteration cap.
CeresNistSolve solveNistWithCeres(const NistProblem& problem, int start, const SolverOptions& stopping);

}  // namespace lrsvo::bench
