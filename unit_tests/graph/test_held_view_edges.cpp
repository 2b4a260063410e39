// The sliding window's held-view edges: a retired keyframe's observation
// whose centre slides with the history's scale, and the prior on that scale.

#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_held_view.h"
#include "lrsvo/edges/edge_scale_prior.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/vertices/so3.h"
#include "test_problems.h"

namespace lrsvo::test {
namespace {

const PinholeIntrinsics kIntrinsics{1280.0, 1275.0, 640.0, 480.0};

// A camera ~100 m above a ground point it sees.
struct HeldViewState {
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  VertexPoint3 point{0};
  VertexScale scale{1};
};

HeldViewState randomState(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  HeldViewState s;
  s.cameraFromWorld.linear() = expSO3(Eigen::Vector3d(0.1 * n(rng), 0.1 * n(rng), n(rng)));
  s.cameraFromWorld.translation() = Eigen::Vector3d(20 * n(rng), 20 * n(rng), 100.0 + 10 * n(rng));
  s.origin = s.cameraFromWorld.inverse() * Eigen::Vector3d(30.0 * n(rng), 3.0 * n(rng), 2.0 * n(rng));
  s.point.setEstimateVector(s.cameraFromWorld.inverse() * Eigen::Vector3d(20 * n(rng), 20 * n(rng), 100.0));
  s.scale.setEstimateVector(Eigen::Matrix<double, 1, 1>(1.0 + 0.05 * n(rng)));
  return s;
}

TEST(HeldViewEdges, AnalyticJacobiansMatchNumeric) {
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 50; ++trial) {
    HeldViewState s = randomState(rng);
    EdgeProjectHeldView view(kIntrinsics, s.cameraFromWorld, s.origin);
    view.setVertex(0, &s.point);
    view.setVertex(1, &s.scale);
    view.setMeasurement(Eigen::Vector2d(600.0, 500.0));
    EXPECT_TRUE(jacobiansMatchNumeric(view, 1e-5, 1e-6)) << "trial " << trial;
    EdgeScalePrior prior;
    prior.setVertex(0, &s.scale);
    prior.setMeasurement(Eigen::Matrix<double, 1, 1>(1.0));
    EXPECT_TRUE(jacobiansMatchNumeric(prior, 1e-6, 1e-8));
  }
}

// At s = 1 the held view is the keyframe's own pose; at s its centre lies at
// origin + s (centre - origin), its orientation unchanged, and the residual
// is that of a base-camera projection from there.
TEST(HeldViewEdges, CentreSlidesWithTheScaleAboutTheOrigin) {
  std::mt19937_64 rng(22);
  HeldViewState s = randomState(rng);
  EdgeProjectHeldView view(kIntrinsics, s.cameraFromWorld, s.origin);
  EXPECT_TRUE(view.cameraFromWorld(1.0).isApprox(s.cameraFromWorld, 1e-12));
  const Eigen::Vector3d centre = s.cameraFromWorld.inverse().translation();
  const Eigen::Isometry3d scaled = view.cameraFromWorld(1.1);
  EXPECT_TRUE(scaled.inverse().translation().isApprox(s.origin + 1.1 * (centre - s.origin), 1e-12));
  EXPECT_TRUE(scaled.linear().isApprox(s.cameraFromWorld.linear(), 1e-12));

  s.scale.setEstimateVector(Eigen::Matrix<double, 1, 1>(1.1));
  view.setVertex(0, &s.point);
  view.setVertex(1, &s.scale);
  view.setMeasurement(Eigen::Vector2d(650.0, 470.0));
  VertexPose pose(2, scaled);
  EdgeProjectBase base(kIntrinsics);
  base.setVertex(0, &pose);
  base.setVertex(1, &s.point);
  base.setMeasurement(Eigen::Vector2d(650.0, 470.0));
  Eigen::Vector2d fromView, fromBase;
  view.computeResidual(fromView);
  base.computeResidual(fromBase);
  EXPECT_LT((fromView - fromBase).norm(), 1e-9);
}

TEST(HeldViewEdges, GraphFileRoundTripKeepsTheHeldView) {
  std::mt19937_64 rng(23);
  HeldViewState s = randomState(rng);
  Graph graph;
  auto* point = graph.addVertex(std::make_unique<VertexPoint3>(0, s.point.estimate()));
  auto* scale = graph.addVertex(std::make_unique<VertexScale>(1, 1.03));
  auto view = std::make_unique<EdgeProjectHeldView>(kIntrinsics, s.cameraFromWorld, s.origin);
  view->setVertex(0, point);
  view->setVertex(1, scale);
  view->setMeasurement(Eigen::Vector2d(610.0, 455.0));
  graph.addEdge(std::move(view));
  auto prior = std::make_unique<EdgeScalePrior>();
  prior->setVertex(0, scale);
  prior->setMeasurement(Eigen::Matrix<double, 1, 1>(1.0));
  prior->setInformation(Eigen::Matrix<double, 1, 1>(1e4));
  graph.addEdge(std::move(prior));

  std::stringstream file;
  saveGraph(graph, file);
  EXPECT_NE(file.str().find(EdgeProjectHeldView::kTypeTag), std::string::npos);
  EXPECT_NE(file.str().find(EdgeScalePrior::kTypeTag), std::string::npos);
  registerEdgeTypes();
  Graph loaded = loadGraph(file, "held view graph");
  EXPECT_DOUBLE_EQ(loaded.cost(), graph.cost());
  EXPECT_GT(graph.cost(), 0.0);
}

}  // namespace
}  // namespace lrsvo::test
