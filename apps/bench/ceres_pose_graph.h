#pragma once

#include <string>

#include "apps/bench/bench_common.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo::bench {

// Solves a pose graph of VertexSE2/EdgeSE2 and VertexSE3Quat/EdgeSE3Quat in
// place with Ceres: one AutoDiff residual per edge with the same error as
// edges/edge_se2.cpp and edges/edge_se3_quat.cpp, whitened by the same upper
// Cholesky factor of the information (so the cost is ours, 1/2 sum r^T Omega r);
// SE2 poses as (x, y, theta) in R^3, SE3 poses as a translation in R^3 and a
// unit quaternion on EigenQuaternionManifold; the graph's fixed vertices held
// constant; Levenberg-Marquardt with SPARSE_NORMAL_CHOLESKY on SuiteSparse.
// Tolerances, iteration cap, starting lambda and threads come from `stopping`.
// Only ceres::Solve is timed. Throws lrsvo::Error on another vertex or edge type.
SolveResult solvePoseGraphWithCeres(Graph& graph, const SolverOptions& stopping);

// One line naming the Ceres version and the configuration used above.
std::string ceresPoseGraphConfiguration();

}  // namespace lrsvo::bench
