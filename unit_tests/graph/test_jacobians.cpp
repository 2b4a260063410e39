// Analytic Jacobians against central differences, and the blocks that
// least-squares and cost edges add to the normal equations.

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/vertices/so3.h"
#include "lrsvo/vertices/vertex_bal_camera.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

constexpr int kStates = 200;

// A rotation of any angle in [0, pi) about a random axis.
Eigen::Vector3d randomAngleAxis(std::mt19937_64& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> angle(0.0, 0.99 * std::numbers::pi);
  const Eigen::Vector3d axis = Eigen::Vector3d{unit(rng), unit(rng), unit(rng)}.normalized();
  return axis * angle(rng);
}

// A camera-frame point inside a 100 degree field of view, 2 to 20 m away along `forward` (+1 or -1).
Eigen::Vector3d randomVisiblePoint(std::mt19937_64& rng, double forward) {
  std::uniform_real_distribution<double> depth(2.0, 20.0), lateral(-0.6, 0.6);
  const double z = depth(rng);
  return {lateral(rng) * z, lateral(rng) * z, forward * z};
}

TEST(Jacobians, BalProjectionMatchesCentralDifferences) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> focal(300.0, 1500.0), k1(-0.2, 0.2), k2(-0.05, 0.05), shift(-5.0, 5.0);
  for (int state = 0; state < kStates; ++state) {
    // Include the identity and tiny rotations, where angle-axis code switches formulas.
    Eigen::Vector3d w = randomAngleAxis(rng);
    if (state == 0) w.setZero();
    if (state == 1) w *= 1e-9 / w.norm();
    Eigen::Matrix<double, 9, 1> parameters;
    const Eigen::Vector3d t{shift(rng), shift(rng), shift(rng)};
    parameters << w, t, focal(rng), k1(rng), k2(rng);
    VertexBalCamera camera(0);
    camera.setEstimateVector(parameters);
    // BAL cameras look down -z: P = R X + t has P.z < 0.
    VertexPoint3 point(1, expSO3(w).transpose() * (randomVisiblePoint(rng, -1.0) - t));
    EdgeBalProjection edge;
    edge.setVertex(0, &camera);
    edge.setVertex(1, &point);
    edge.setMeasurement(Eigen::Vector2d{shift(rng), shift(rng)});
    EXPECT_TRUE(jacobiansMatchNumeric(edge, 1e-6, 1e-6)) << "state " << state;
  }
}

// Random pose (camera-from-world) and a point in front of it.
struct PoseAndPoint {
  VertexPose pose{0};
  VertexPoint3 point{1};
};

void randomize(PoseAndPoint& state, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> shift(-5.0, 5.0);
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
  cameraFromWorld.linear() = expSO3(randomAngleAxis(rng));
  cameraFromWorld.translation() = Eigen::Vector3d{shift(rng), shift(rng), shift(rng)};
  state.pose.setCameraFromWorld(cameraFromWorld);
  state.point.setEstimateVector(cameraFromWorld.inverse() * randomVisiblePoint(rng, 1.0));
}

TEST(Jacobians, PinholeMatchesCentralDifferences) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> focal(100.0, 1000.0);
  PoseAndPoint state;
  for (int k = 0; k < kStates; ++k) {
    randomize(state, rng);
    EdgePinhole edge;
    edge.focal = focal(rng);
    edge.setVertex(0, &state.pose);
    edge.setVertex(1, &state.point);
    EXPECT_TRUE(jacobiansMatchNumeric(edge)) << "state " << k;
  }
}

TEST(Jacobians, ScaledPinholeMatchesCentralDifferences) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> scale(-0.3, 0.3);
  PoseAndPoint state;
  VertexFocalScale shared(2);
  for (int k = 0; k < kStates; ++k) {
    randomize(state, rng);
    shared.setEstimateVector(Eigen::Matrix<double, 1, 1>(scale(rng)));
    EdgeScaledPinhole edge;
    edge.setVertex(0, &state.pose);
    edge.setVertex(1, &state.point);
    edge.setVertex(2, &shared);
    EXPECT_TRUE(jacobiansMatchNumeric(edge)) << "state " << k;
  }
}

// The checker must catch a wrong Jacobian, or the tests above prove nothing.
class EdgeWithWrongRotationJacobian : public EdgePinhole {
 public:
  void computeJacobians() override {
    EdgePinhole::computeJacobians();
    jacobian<0>().col(4) *= -1.0;
  }
};

TEST(Jacobians, CheckerRejectsAWrongJacobian) {
  std::mt19937_64 rng(14);
  PoseAndPoint state;
  randomize(state, rng);
  EdgeWithWrongRotationJacobian edge;
  edge.setVertex(0, &state.pose);
  edge.setVertex(1, &state.point);
  const ::testing::AssertionResult result = jacobiansMatchNumeric(edge);
  EXPECT_FALSE(result);
  EXPECT_NE(std::string(result.message()).find("vertex 0 column 4"), std::string::npos) << result.message();
}

// H_ab = rho'(s) J_a^T Omega J_b and g_a = rho'(s) J_a^T Omega r, with
// s = r^T Omega r and cost 1/2 rho(s): the IRLS blocks of a least-squares edge.
TEST(Jacobians, LeastSquaresEdgeAddsWeightedGaussNewtonBlocks) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> offset(-8.0, 8.0), entry(-0.4, 0.4);
  for (const char* kernelName : {"", "Huber", "Cauchy", "Tukey"}) {
    for (int k = 0; k < 20; ++k) {
      PoseAndPoint state;
      randomize(state, rng);
      EdgePinhole edge;
      edge.setVertex(0, &state.pose);
      edge.setVertex(1, &state.point);
      Eigen::Vector2d prediction;
      edge.computeResidual(prediction);
      edge.setMeasurement(prediction + Eigen::Vector2d{offset(rng), offset(rng)});
      Eigen::Matrix2d root;
      root << 1.0 + entry(rng), 0.0, entry(rng), 1.0 + entry(rng);
      const Eigen::Matrix2d information = root * root.transpose();
      edge.setInformation(information);
      std::shared_ptr<RobustKernel> kernel;
      if (*kernelName) edge.setRobustKernel(kernel = makeRobustKernel(kernelName, 5.0));

      edge.computeNumericJacobians();
      const Eigen::Matrix<double, 2, 6> jPose = edge.jacobian<0>();
      const Eigen::Matrix<double, 2, 3> jPoint = edge.jacobian<1>();
      Eigen::Vector2d r;
      edge.computeResidual(r);
      const double s = r.dot(information * r);
      double weight = 1.0;
      const double rho = kernel ? kernel->evaluate(s, &weight) : s;

      const double cost = edge.linearize();
      EXPECT_NEAR(cost, 0.5 * rho, 1e-12 * rho) << kernelName;
      EXPECT_NEAR(edge.cost(), 0.5 * rho, 1e-12 * rho) << kernelName;

      const Eigen::Matrix<double, 6, 6> expectedPosePose = weight * jPose.transpose() * information * jPose;
      const Eigen::Matrix<double, 6, 3> expectedPosePoint = weight * jPose.transpose() * information * jPoint;
      const Eigen::Matrix3d expectedPointPoint = weight * jPoint.transpose() * information * jPoint;
      Eigen::Matrix<double, 6, 6> posePose = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 3> posePoint = Eigen::Matrix<double, 6, 3>::Zero();
      Eigen::Matrix<double, 3, 6> pointPose = Eigen::Matrix<double, 3, 6>::Zero();
      Eigen::Matrix3d pointPoint = Eigen::Matrix3d::Zero();
      edge.addHessianBlock(0, 0, posePose.data(), 6);
      edge.addHessianBlock(0, 1, posePoint.data(), 6);
      edge.addHessianBlock(1, 0, pointPose.data(), 3);
      edge.addHessianBlock(1, 1, pointPoint.data(), 3);
      const double scale = expectedPosePose.norm() + 1e-12;
      EXPECT_LE((posePose - expectedPosePose).norm(), 1e-6 * scale) << kernelName;
      EXPECT_LE((posePoint - expectedPosePoint).norm(), 1e-6 * scale) << kernelName;
      EXPECT_LE((pointPose - expectedPosePoint.transpose()).norm(), 1e-6 * scale) << kernelName;
      EXPECT_LE((pointPoint - expectedPointPoint).norm(), 1e-6 * scale) << kernelName;

      Eigen::Matrix<double, 6, 1> gPose = Eigen::Matrix<double, 6, 1>::Zero();
      Eigen::Vector3d gPoint = Eigen::Vector3d::Zero();
      edge.addGradient(0, gPose.data());
      edge.addGradient(1, gPoint.data());
      const Eigen::Matrix<double, 6, 1> expectedPose = weight * jPose.transpose() * information * r;
      const Eigen::Vector3d expectedPoint = weight * jPoint.transpose() * information * r;
      EXPECT_LE((gPose - expectedPose).norm(), 1e-6 * (expectedPose.norm() + 1e-12)) << kernelName;
      EXPECT_LE((gPoint - expectedPoint).norm(), 1e-6 * (expectedPose.norm() + 1e-12)) << kernelName;
    }
  }
}

struct CostEdgeFixture {
  Graph graph;
  VertexPoint3* point;
  VertexFocalScale* scale;
  std::vector<EdgeQuadraticCost*> edges;

  explicit CostEdgeFixture(std::uint64_t seed, int edgeCount) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> unit(0.0, 1.0);
    point = graph.addVertex(std::make_unique<VertexPoint3>(7, Eigen::Vector3d{unit(rng), unit(rng), unit(rng)}));
    scale = graph.addVertex(std::make_unique<VertexFocalScale>(3));
    scale->setEstimateVector(Eigen::Matrix<double, 1, 1>(unit(rng)));
    for (int k = 0; k < edgeCount; ++k) {
      auto edge = std::make_unique<EdgeQuadraticCost>();
      const Eigen::Matrix4d a = Eigen::Matrix4d::NullaryExpr([&] { return unit(rng); });
      edge->weight = a * a.transpose() + Eigen::Matrix4d::Identity();
      edge->centre = Eigen::Vector4d::NullaryExpr([&] { return unit(rng); });
      edge->setVertex(0, point);
      edge->setVertex(1, scale);
      edges.push_back(graph.addEdge(std::move(edge)));
    }
  }
  Eigen::Vector4d x() const {
    return {point->estimate().x(), point->estimate().y(), point->estimate().z(), scale->estimate()[0]};
  }
};

TEST(Jacobians, CostEdgeAddsItsGradientAndHessian) {
  CostEdgeFixture fixture(21, 1);
  EdgeQuadraticCost& edge = *fixture.edges[0];
  const Eigen::Vector4d d = fixture.x() - edge.centre;
  EXPECT_DOUBLE_EQ(edge.linearize(), 0.5 * d.dot(edge.weight * d));

  // Blocks written into their places of one 4x4 matrix (leading dimension 4).
  Eigen::Matrix4d hessian = Eigen::Matrix4d::Zero();
  edge.addHessianBlock(0, 0, &hessian(0, 0), 4);
  edge.addHessianBlock(0, 1, &hessian(0, 3), 4);
  edge.addHessianBlock(1, 0, &hessian(3, 0), 4);
  edge.addHessianBlock(1, 1, &hessian(3, 3), 4);
  EXPECT_EQ(hessian, edge.weight);

  const Eigen::Vector4d expectedGradient = edge.weight * d;
  Eigen::Vector4d gradient = Eigen::Vector4d::Zero();
  edge.addGradient(0, &gradient[0]);
  edge.addGradient(1, &gradient[3]);
  EXPECT_LE((gradient - expectedGradient).norm(), 1e-12 * expectedGradient.norm());
}

// Two cost edges on the same vertices: the system holds the sums, in the
// blocks of whatever order the system chose.
TEST(Jacobians, CostEdgesSumIntoTheBlockSystem) {
  for (bool schurOrdering : {false, true}) {
    CostEdgeFixture fixture(22, 2);
    BlockSystem system(fixture.graph, schurOrdering);
    const double cost = system.fill(1);
    const Eigen::Matrix4d weight = fixture.edges[0]->weight + fixture.edges[1]->weight;
    const Eigen::Vector4d gradient = fixture.edges[0]->weight * (fixture.x() - fixture.edges[0]->centre) +
                                     fixture.edges[1]->weight * (fixture.x() - fixture.edges[1]->centre);
    EXPECT_NEAR(cost, fixture.edges[0]->cost() + fixture.edges[1]->cost(), 1e-12 * cost);

    // Permute (point, scale) into the system's order.
    const int p = system.offset(system.blockOf(fixture.point)), s = system.offset(system.blockOf(fixture.scale));
    Eigen::Matrix4d expected;
    Eigen::Vector4d expectedGradient;
    const int index[4] = {p, p + 1, p + 2, s};
    for (int r = 0; r < 4; ++r) {
      expectedGradient[index[r]] = gradient[r];
      for (int c = 0; c < 4; ++c) expected(index[r], index[c]) = weight(r, c);
    }
    EXPECT_LE((denseHessian(system) - expected).norm(), 1e-12 * expected.norm()) << schurOrdering;
    EXPECT_LE((system.gradient() - expectedGradient).norm(), 1e-12 * expectedGradient.norm()) << schurOrdering;
    EXPECT_EQ(system.freeCount(), schurOrdering ? 1 : 2);
  }
}

// With the scale fixed, only the point's block and gradient remain.
TEST(Jacobians, CostEdgeOnAFixedVertexAddsOnlyTheFreeBlock) {
  CostEdgeFixture fixture(23, 1);
  fixture.scale->setFixed(true);
  BlockSystem system(fixture.graph, false);
  system.fill(1);
  ASSERT_EQ(system.blockCount(), 1);
  const EdgeQuadraticCost& edge = *fixture.edges[0];
  EXPECT_EQ(Eigen::Matrix3d(denseHessian(system)), (edge.weight.topLeftCorner<3, 3>()));
  const Eigen::Vector3d expected = (edge.weight * (fixture.x() - edge.centre)).head<3>();
  EXPECT_LE((system.gradient() - expected).norm(), 1e-12 * expected.norm());
}

}  // namespace
}  // namespace lrsvo::test
