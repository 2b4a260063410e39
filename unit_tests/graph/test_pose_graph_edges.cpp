// The pose-graph types: SE2 and SE3 poses, their relative-pose edges'
// Jacobians against central differences, and their graph-file round trip.

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/vertices/so3.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
// Named, so that helpers stay apart from other files' in a unity build.
namespace pose_graph_edges {
namespace {

constexpr int kStates = 200;
constexpr double kPi = std::numbers::pi;
// Positions are drawn in [-kExtent, kExtent] per coordinate, so every residual
// component is below kResidualBound = 2 sqrt(3) kExtent + the measurement's offset.
constexpr double kExtent = 5.0;
constexpr double kResidualBound = 4.0 * kExtent;
// BaseEdge's central differences step h = 1e-6 through oplus. Their error is
// rounding, about kOperations eps |r| / h for a residual of some tens of
// operations, plus truncation h^2 / 6 |r'''| (|r'''| <= kResidualBound for these
// rotations and translations): together below the tolerance, with no slack read off a run.
constexpr double kStep = 1e-6;
constexpr double kOperations = 50.0;
constexpr double kJacobianTolerance = kOperations * std::numeric_limits<double>::epsilon() * kResidualBound / kStep +
                                      kStep * kStep / 6.0 * kResidualBound;

Eigen::Vector3d randomAngleAxis(std::mt19937_64& rng, double maxAngle) {
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> angle(0.0, maxAngle);
  return Eigen::Vector3d{unit(rng), unit(rng), unit(rng)}.normalized() * angle(rng);
}

Eigen::Isometry3d randomPose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> shift(-kExtent, kExtent);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = expSO3(randomAngleAxis(rng, 0.99 * kPi));
  pose.translation() = Eigen::Vector3d{shift(rng), shift(rng), shift(rng)};
  return pose;
}

TEST(PoseGraphTypes, WrapAngleMapsIntoTheHalfOpenInterval) {
  EXPECT_EQ(wrapAngle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(wrapAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(-kPi), kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(3.0 * kPi), kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(-0.5 * kPi - 4.0 * kPi), -0.5 * kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(2.0 * kPi - 0.25), -0.25);
}

TEST(PoseGraphTypes, SE2UpdateAddsAndWrapsTheHeading) {
  VertexSE2 pose(0, Eigen::Vector3d(1.0, 2.0, 3.0));
  const Eigen::Vector3d delta(0.5, -0.25, 0.5);
  pose.oplus(delta.data());
  EXPECT_EQ(pose.translation(), Eigen::Vector2d(1.5, 1.75));
  EXPECT_DOUBLE_EQ(pose.angle(), 3.5 - 2.0 * kPi);
}

TEST(PoseGraphTypes, SE3UpdateMovesTranslationInTheWorldAndRotationInTheBody) {
  std::mt19937_64 rng(21);
  const Eigen::Isometry3d start = randomPose(rng);
  VertexSE3Quat pose(0, start);
  Eigen::Matrix<double, 6, 1> delta;
  delta << 0.1, -0.2, 0.3, 0.05, -0.04, 0.03;
  pose.oplus(delta.data());
  EXPECT_TRUE(pose.translation().isApprox(start.translation() + delta.head<3>(), 1e-15));
  EXPECT_TRUE(pose.rotation().isApprox(start.linear() * expSO3(delta.tail<3>()), 1e-14));
}

TEST(PoseGraphTypes, QuaternionsOffUnitNormAreRejected) {
  VertexSE3Quat pose(3);
  const double nearlyUnit[7] = {0, 0, 0, 0, 0, 0, 1.0 + 0.5 * VertexSE3Quat::kQuaternionNormTolerance};
  EXPECT_NO_THROW(pose.setEstimate(nearlyUnit));
  const double tooLong[7] = {0, 0, 0, 0, 0, 0, 1.0 + 2.0 * VertexSE3Quat::kQuaternionNormTolerance};
  EXPECT_THROW(pose.setEstimate(tooLong), Error);
  const double zero[7] = {0, 0, 0, 0, 0, 0, 0};
  EXPECT_THROW(pose.setEstimate(zero), Error);
  EdgeSE3Quat edge;
  EXPECT_THROW(edge.setRelativePose(Eigen::Vector3d::Zero(), Eigen::Quaterniond(0.5, 0.0, 0.0, 0.0)), Error);
}

TEST(PoseGraphTypes, InformationMustBeSymmetricPositiveDefinite) {
  EdgeSE2 edge;
  Eigen::Matrix3d asymmetric = Eigen::Matrix3d::Identity();
  asymmetric(0, 1) = 0.5;
  EXPECT_THROW(edge.setInformation(asymmetric), Error);
  EXPECT_THROW(edge.setInformation(Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal()), Error);
  EXPECT_NO_THROW(edge.setInformation(Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal()));
}

TEST(Jacobians, SE2EdgeMatchesCentralDifferences) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> shift(-kExtent, kExtent), heading(-kPi, kPi), offset(-0.5, 0.5);
  for (int state = 0; state < kStates; ++state) {
    VertexSE2 from(0, Eigen::Vector3d(shift(rng), shift(rng), heading(rng)));
    VertexSE2 to(1, Eigen::Vector3d(shift(rng), shift(rng), heading(rng)));
    // The measurement is the true relative pose moved by up to 0.5 in each
    // component, so the heading residual stays clear of its wrap at +-pi.
    const Eigen::Isometry2d relative = from.worldFromBody().inverse() * to.worldFromBody();
    EdgeSE2 edge;
    edge.setVertex(0, &from);
    edge.setVertex(1, &to);
    edge.setMeasurement(Eigen::Vector3d(relative.translation().x() + offset(rng),
                                        relative.translation().y() + offset(rng),
                                        Eigen::Rotation2Dd(relative.linear()).angle() + offset(rng)));
    EXPECT_TRUE(jacobiansMatchNumeric(edge, 0.0, kJacobianTolerance)) << "state " << state;
  }
}

TEST(Jacobians, SE3QuatEdgeMatchesCentralDifferences) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> offset(-0.5, 0.5);
  for (int state = 0; state < kStates; ++state) {
    VertexSE3Quat from(0, randomPose(rng));
    VertexSE3Quat to(1, randomPose(rng));
    // The true relative pose moved by up to 0.5 rad and 0.5 per axis: the
    // error quaternion's w stays well above 0, where its sign would flip.
    Eigen::Isometry3d relative = from.worldFromBody().inverse() * to.worldFromBody();
    relative.linear() = relative.linear() * expSO3(randomAngleAxis(rng, 0.5));
    relative.translation() += Eigen::Vector3d{offset(rng), offset(rng), offset(rng)};
    EdgeSE3Quat edge;
    edge.setVertex(0, &from);
    edge.setVertex(1, &to);
    edge.setRelativePose(relative);
    EXPECT_TRUE(jacobiansMatchNumeric(edge, 0.0, kJacobianTolerance)) << "state " << state;
  }
}

TEST(PoseGraphTypes, ResidualIsZeroAtTheMeasuredRelativePose) {
  std::mt19937_64 rng(24);
  VertexSE3Quat from(0, randomPose(rng));
  VertexSE3Quat to(1, randomPose(rng));
  EdgeSE3Quat edge;
  edge.setVertex(0, &from);
  edge.setVertex(1, &to);
  edge.setRelativePose(from.worldFromBody().inverse() * to.worldFromBody());
  EdgeSE3Quat::Residual residual;
  edge.computeResidual(residual);
  // Rounding of a few products of rotations and translations of size kExtent.
  EXPECT_LT(residual.norm(), kOperations * std::numeric_limits<double>::epsilon() * kResidualBound);
}

TEST(GraphFile, PoseGraphTypesRoundTripExactly) {
  registerEdgeTypes();
  std::mt19937_64 rng(25);
  Graph graph;
  auto* a = graph.addVertex(std::make_unique<VertexSE2>(0, Eigen::Vector3d(0.1, 1.0 / 3.0, 4.0)));
  auto* b = graph.addVertex(std::make_unique<VertexSE2>(1, Eigen::Vector3d(-2.0 / 7.0, 5.0, -0.3)));
  a->setFixed(true);
  auto planar = std::make_unique<EdgeSE2>();
  planar->setVertex(0, a);
  planar->setVertex(1, b);
  planar->setMeasurement(Eigen::Vector3d(1.0 / 3.0, -0.2, 0.7));
  Eigen::Matrix3d information;
  information << 2.0, 0.1, 0.2, 0.1, 3.0, 1.0 / 3.0, 0.2, 1.0 / 3.0, 5.0;
  planar->setInformation(information);
  graph.addEdge(std::move(planar));
  auto* c = graph.addVertex(std::make_unique<VertexSE3Quat>(2, randomPose(rng)));
  auto* d = graph.addVertex(std::make_unique<VertexSE3Quat>(3, randomPose(rng)));
  auto spatial = std::make_unique<EdgeSE3Quat>();
  spatial->setVertex(0, c);
  spatial->setVertex(1, d);
  spatial->setRelativePose(randomPose(rng));
  spatial->setRobustKernel(makeRobustKernel("Huber", 0.5));
  graph.addEdge(std::move(spatial));

  const std::string text = saveToString(graph);
  for (const char* tag : {"POSE_SE2", "POSE_SE3_QUAT", "RELATIVE_POSE_SE2", "RELATIVE_POSE_SE3_QUAT"})
    EXPECT_NE(text.find(tag), std::string::npos) << tag;
  const Graph loaded = loadFromString(text);
  EXPECT_EQ(saveToString(loaded), text);
  EXPECT_EQ(loaded.estimates(), graph.estimates());
  EXPECT_EQ(loaded.cost(), graph.cost());
}

}  // namespace
}  // namespace pose_graph_edges
}  // namespace lrsvo::test
