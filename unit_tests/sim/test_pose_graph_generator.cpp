// Generated pose graphs: the same seed gives the same graph, the shapes have
// their loop closures, the noise has the stated size, and the graphs optimise.

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/edges/g2o_file.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/sim/pose_graph_generator.h"

namespace lrsvo::test {
// Named, so that helpers stay apart from other files' in a unity build.
namespace pose_graph_generator {
namespace {

std::string g2oText(const Graph& graph) {
  std::ostringstream out;
  saveG2o(graph, out);
  return out.str();
}

PoseGraphOptions options(PoseGraphShape shape, int dimension, int poses, std::uint64_t seed) {
  PoseGraphOptions o;
  o.shape = shape;
  o.dimension = dimension;
  o.poses = poses;
  o.seed = seed;
  return o;
}

TEST(PoseGraphGenerator, SameSeedSameGraphOtherSeedOtherGraph) {
  for (const auto& [shape, dimension] : {std::pair{PoseGraphShape::kSphere, 3}, std::pair{PoseGraphShape::kGrid, 2},
                                         std::pair{PoseGraphShape::kGrid, 3}}) {
    const std::string a = g2oText(generatePoseGraph(options(shape, dimension, 300, 7)));
    EXPECT_EQ(g2oText(generatePoseGraph(options(shape, dimension, 300, 7))), a);
    EXPECT_NE(g2oText(generatePoseGraph(options(shape, dimension, 300, 8))), a);
  }
}

TEST(PoseGraphGenerator, ShapesHaveOdometryAndLoopClosures) {
  const Graph sphere = generatePoseGraph(options(PoseGraphShape::kSphere, 3, 800, 1));
  ASSERT_EQ(sphere.vertices().size(), 800u);
  // 20 rings of 40 poses: 799 odometry edges and one closure per pose past the first ring.
  EXPECT_EQ(sphere.edges().size(), 799u + 760u);
  for (int dimension : {2, 3}) {
    const Graph grid = generatePoseGraph(options(PoseGraphShape::kGrid, dimension, 1000, 1));
    ASSERT_EQ(grid.vertices().size(), 1000u);
    // A box of about 250 cells visited by 1000 poses: most poses return to a visited cell.
    EXPECT_GT(grid.edges().size(), 999u + 500u) << dimension << "D";
    EXPECT_LT(grid.edges().size(), 999u + 1000u) << dimension << "D";
  }
  EXPECT_NE(
      dynamic_cast<const EdgeSE2*>(generatePoseGraph(options(PoseGraphShape::kGrid, 2, 10, 1)).edges().front().get()),
      nullptr);
}

TEST(PoseGraphGenerator, BadOptionsAreRejected) {
  EXPECT_THROW(generatePoseGraph(options(PoseGraphShape::kSphere, 2, 100, 1)), Error);
  EXPECT_THROW(generatePoseGraph(options(PoseGraphShape::kGrid, 4, 100, 1)), Error);
  EXPECT_THROW(generatePoseGraph(options(PoseGraphShape::kGrid, 2, 1, 1)), Error);
  EXPECT_THROW(poseGraphShapeFromName("torus"), Error);
  EXPECT_EQ(poseGraphShapeFromName("grid"), PoseGraphShape::kGrid);
}

// At the start the odometry edges fit exactly (the start is chained from
// them); the loop closures carry the drift. Optimised, each edge's whitened
// residual is about its noise: the cost per residual dimension is near 1/2
// (chi-square with n - 6 (N - 1) degrees of freedom over n, n = 6 edges).
TEST(PoseGraphGenerator, OptimisedCostMatchesTheNoise) {
  for (const auto& [shape, dimension] : {std::pair{PoseGraphShape::kSphere, 3}, std::pair{PoseGraphShape::kGrid, 2},
                                         std::pair{PoseGraphShape::kGrid, 3}}) {
    Graph graph = generatePoseGraph(options(shape, dimension, 400, 3));
    graph.vertices().front()->setFixed(true);
    const SolverSummary summary = Optimizer(SolverOptions::fromName("lm_cholmod")).optimize(graph);
    const int d = dimension == 2 ? 3 : 6;
    const double residuals = static_cast<double>(d * graph.edges().size());
    const double freedom = residuals - static_cast<double>(d * (graph.vertices().size() - 1));
    // E[2 cost] = freedom, standard deviation sqrt(2 freedom); allow 5 of them.
    EXPECT_LT(summary.finalCost, summary.initialCost);
    EXPECT_NEAR(2.0 * summary.finalCost, freedom, 5.0 * std::sqrt(2.0 * freedom))
        << "shape " << static_cast<int>(shape) << ", " << dimension << "D";
  }
}

}  // namespace
}  // namespace pose_graph_generator
}  // namespace lrsvo::test
