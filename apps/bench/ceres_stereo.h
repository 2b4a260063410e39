#pragma once

#include <unordered_map>
#include <vector>

#include <ceres/problem.h>
#include <ceres/types.h>

#include "apps/bench/bench_common.h"
#include "lrsvo/constraints/bounds.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo::bench {

// Ceres' model of one of our stereo graphs, set up as a Ceres user would, from
// the graph's current estimates:
// - VertexPose: 7 numbers (t, quaternion x y z w), the layout of its graph
//   files, with the manifold R^3 x EigenQuaternionManifold. Ceres' quaternion
//   update is left-multiplicative like ours (R <- Exp(dphi) R); its translation
//   update is t + dt where ours is Exp(dphi) t + dt: another chart of the same
//   manifold, so the same optimum by different steps.
// - VertexPoint3 (3), VertexStereoExtrinsic (x y z roll pitch yaw), VertexScale
//   (kappa): Euclidean, the same numbers.
// - EdgeProjectBase, EdgeProjectSecondary, EdgeProjectSecondaryScaled: one
//   AutoDiff residual each, the projections of edges/edge_project_base.cpp and
//   edges/secondary_projection.cpp, whitened by the edge's square-root
//   information, with the edge's robust kernel as the equivalent Ceres loss
//   (Huber, Cauchy and Tukey share our rho; both costs are 1/2 rho(|r|^2)).
// Fixed vertices are constant blocks, marginalised ones (points) form
// elimination group 0 and the rest group 1, and `bounds` become
// SetParameterLowerBound / SetParameterUpperBound.
class CeresStereoModel {
 public:
  // Throws lrsvo::Error on a vertex or edge type it does not model, or a bound
  // on a vertex that is not in the graph.
  CeresStereoModel(const Graph& graph, const Bounds& bounds);
  CeresStereoModel(const CeresStereoModel&) = delete;
  CeresStereoModel& operator=(const CeresStereoModel&) = delete;

  // 1/2 sum rho(|r|^2) at the model's current values.
  double cost();
  // Solves with Ceres' Levenberg-Marquardt, stopping by our rules
  // (ceresSolverOptions); only ceres::Solve is timed.
  SolveResult solve(const SolverOptions& stopping, ceres::LinearSolverType linearSolver);
  // Writes the model's values into the vertices of the same ids in `graph`
  // (the graph it was built from, or a copy of it).
  void copyTo(Graph& graph) const;

 private:
  struct Block {
    int vertexId;
    bool fixed;
    bool marginalized;
    bool pose;  // a VertexPose, on the pose manifold
    std::vector<double> values;
  };

  double* block(const Vertex* vertex);
  void addEdge(const Edge& edge);

  ceres::Problem problem_;
  std::vector<Block> blocks_;  // the problem holds pointers into each block's values
  std::unordered_map<const Vertex*, int> blockIndex_;
};

}  // namespace lrsvo::bench
