// The two graph pieces the initialisers add: the centre-distance prior that
// holds a monocular map's unit, and kappa's covariance from the information.

#include <random>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include "lrsvo/edges/edge_centre_distance.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/marginal_covariance.h"
#include "lrsvo/sim/window_problem.h"
#include "lrsvo/vertices/so3.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

Eigen::Isometry3d randomPose(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = expSO3(Eigen::Vector3d(n(rng), n(rng), n(rng)));
  pose.translation() = Eigen::Vector3d(5 * n(rng), 5 * n(rng), 5 * n(rng));
  return pose;
}

TEST(InitializerGauge, CentreDistanceMatchesHandComputedDistanceAndNumericJacobians) {
  VertexPose a(0), b(1);
  Eigen::Isometry3d poseB = Eigen::Isometry3d::Identity();
  poseB.linear() = expSO3(Eigen::Vector3d(0.1, 0.2, 0.3));
  poseB.translation() = -poseB.linear() * Eigen::Vector3d(3.0, 4.0, 0.0);  // centre (3, 4, 0)
  b.setCameraFromWorld(poseB);
  EdgeCentreDistance edge;
  edge.setVertex(0, &a);
  edge.setVertex(1, &b);
  edge.setMeasurement(Eigen::Matrix<double, 1, 1>(4.0));
  Eigen::Matrix<double, 1, 1> residual;
  edge.computeResidual(residual);
  EXPECT_NEAR(residual[0], 1.0, 1e-12);  // |(3, 4, 0)| - 4

  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    a.setCameraFromWorld(randomPose(rng));
    b.setCameraFromWorld(randomPose(rng));
    EXPECT_TRUE(jacobiansMatchNumeric(edge, 1e-6, 1e-7)) << "trial " << trial;
  }
}

// A small window: `frames` poses, `points` points, each seen by 2 to all of the frames.
WindowProblemOptions smallWindow(int frames, int points) {
  WindowProblemOptions options;
  options.frames = frames;
  options.points = points;
  options.minTrackLength = 2;
  options.maxTrackLength = frames;
  return options;
}

// The covariance from the Schur-reduced information equals the block of the
// inverse of the whole (dense) information, with held coordinates removed.
TEST(InitializerGauge, MarginalCovarianceEqualsTheDenseInverse) {
  WindowProblemOptions options = smallWindow(4, 40);
  options.withScale = true;
  options.startScale = 0.8;
  WindowProblem problem = makeWindowProblem(options);
  const std::vector<HeldCoordinate> held = {{problem.extrinsic, 0}, {problem.extrinsic, 1}, {problem.extrinsic, 2}};
  const Eigen::MatrixXd covariance = marginalCovariance(problem.graph, {problem.scale}, held);
  const Eigen::MatrixXd joint = marginalCovariance(problem.graph, {problem.poses[3], problem.scale}, held);

  BlockSystem system(problem.graph, true);
  system.fill(1);
  const int n = system.scalarCount();
  Eigen::MatrixXd dense(n, n);
  for (int c = 0; c < n; ++c) dense.col(c) = system.multiply(Eigen::VectorXd::Unit(n, c));
  std::vector<int> kept;
  const int heldOffset = system.offset(system.blockOf(problem.extrinsic));
  for (int i = 0; i < n; ++i)
    if (i < heldOffset || i >= heldOffset + 3) kept.push_back(i);
  Eigen::MatrixXd reduced(kept.size(), kept.size());
  for (std::size_t r = 0; r < kept.size(); ++r)
    for (std::size_t c = 0; c < kept.size(); ++c) reduced(r, c) = dense(kept[r], kept[c]);
  const Eigen::MatrixXd inverse = reduced.ldlt().solve(Eigen::MatrixXd::Identity(kept.size(), kept.size()));
  const int scaleOffset = system.offset(system.blockOf(problem.scale));
  const int scaleRow = static_cast<int>(std::find(kept.begin(), kept.end(), scaleOffset) - kept.begin());
  ASSERT_EQ(covariance.rows(), 1);
  EXPECT_GT(covariance(0, 0), 0.0);
  EXPECT_NEAR(covariance(0, 0), inverse(scaleRow, scaleRow), 1e-6 * inverse(scaleRow, scaleRow));
  // A joint request returns the blocks and their correlation in the order asked.
  const int poseOffset = system.offset(system.blockOf(problem.poses[3]));
  ASSERT_EQ(joint.rows(), 7);
  EXPECT_NEAR(joint(6, 6), covariance(0, 0), 1e-9 * covariance(0, 0));
  for (int i = 0; i < 6; ++i) {
    const int row = static_cast<int>(std::find(kept.begin(), kept.end(), poseOffset + i) - kept.begin());
    EXPECT_NEAR(joint(i, 6), inverse(row, scaleRow), 1e-6 * std::sqrt(inverse(row, row) * inverse(scaleRow, scaleRow)));
    EXPECT_NEAR(joint(i, i), inverse(row, row), 1e-6 * inverse(row, row));
  }
}

// Each column is one Schur solve, split over rows of the reduced system: the
// split must not change a digit. A combination's variance is one such solve.
TEST(InitializerGauge, MarginalCovarianceIsTheSameOnAnyThreadCount) {
  WindowProblemOptions options = smallWindow(5, 60);
  options.withScale = true;
  WindowProblem problem = makeWindowProblem(options);
  const std::vector<HeldCoordinate> held = {{problem.extrinsic, 0}, {problem.extrinsic, 1}, {problem.extrinsic, 2}};
  const std::vector<const Vertex*> targets = {problem.poses[2], problem.scale, problem.poses[4]};
  const Eigen::MatrixXd one = marginalCovariance(problem.graph, targets, held, 1);
  ASSERT_EQ(one.rows(), 13);
  for (int threads : {2, 3}) {
    const Eigen::MatrixXd many = marginalCovariance(problem.graph, targets, held, threads);
    EXPECT_TRUE(many == one) << threads << " threads";
  }
  EXPECT_THROW(marginalCovariance(problem.graph, targets, held, 0), Error);

  // One combination's variance by one solve is that of the covariance: c^T Sigma c
  // (to the same relative tolerance as the dense inverse above).
  const Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(13, -1.0, 2.0);
  const double variance = marginalVariance(problem.graph, targets, c, held, 2);
  EXPECT_NEAR(variance, c.dot(one * c), 1e-6 * variance);
  EXPECT_THROW(marginalVariance(problem.graph, targets, Eigen::VectorXd::Ones(12), held), Error);
}

TEST(InitializerGauge, MarginalCovarianceRefusesAFixedVertex) {
  WindowProblem problem = makeWindowProblem(smallWindow(3, 20));
  EXPECT_THROW(marginalCovariance(problem.graph, {problem.poses[0]}), Error);
}

}  // namespace
}  // namespace lrsvo::test
