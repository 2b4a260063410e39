// S changing linearly across a window: the secondary projection through
// s + dt * rate, and the prior on the rate.

#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "lrsvo/edges/edge_extrinsic_rate_prior.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/edges/edge_project_secondary_drifting.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/graph_file.h"
#include "lrsvo/vertices/so3.h"
#include "test_problems.h"

namespace lrsvo::test {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;
const SecondaryCamera kCamera{1, {1667.4, 1667.4, 640.0, 480.0}};

// A base pose ~100 m above a ground point, a flexed S near (0.7 m, 0, 0) and a rate.
struct DriftingState {
  VertexPose pose{0};
  VertexPoint3 point{1};
  VertexStereoExtrinsic extrinsic{2};
  VertexExtrinsicRate rate{3};
};

void randomise(DriftingState& s, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
  cameraFromWorld.linear() = expSO3(Eigen::Vector3d(0.1 * n(rng), 0.1 * n(rng), n(rng)));
  cameraFromWorld.translation() = Eigen::Vector3d(20 * n(rng), 20 * n(rng), 100.0 + 10 * n(rng));
  s.pose.setCameraFromWorld(cameraFromWorld);
  s.point.setEstimateVector(cameraFromWorld.inverse() * Eigen::Vector3d(20 * n(rng), 20 * n(rng), 100.0));
  Vector6 extrinsic, rate;
  for (int i = 0; i < 3; ++i) {
    extrinsic[i] = (i == 0 ? 0.7 : 0.0) + 1e-3 * n(rng);
    extrinsic[i + 3] = 1e-2 * n(rng);
    rate[i] = 1e-3 * n(rng);
    rate[i + 3] = 1e-2 * n(rng);
  }
  s.extrinsic.setEstimateVector(extrinsic);
  s.rate.setEstimateVector(rate);
}

TEST(ExtrinsicRateEdges, AnalyticJacobiansMatchNumeric) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> dt(-2.0, 0.5);
  for (int trial = 0; trial < 50; ++trial) {
    DriftingState s;
    randomise(s, rng);
    EdgeProjectSecondaryDrifting edge(kCamera, dt(rng));
    edge.setVertex(0, &s.pose);
    edge.setVertex(1, &s.point);
    edge.setVertex(2, &s.extrinsic);
    edge.setVertex(3, &s.rate);
    edge.setMeasurement(Eigen::Vector2d(600.0, 500.0));
    EXPECT_TRUE(jacobiansMatchNumeric(edge, 1e-5, 1e-6)) << "trial " << trial;
    EdgeExtrinsicRatePrior prior;
    prior.setVertex(0, &s.rate);
    EXPECT_TRUE(jacobiansMatchNumeric(prior, 1e-6, 1e-8));
  }
}

// The drifting edge at dt is the constant-S edge through s + dt * rate; at
// dt = 0 the rate does not matter.
TEST(ExtrinsicRateEdges, ProjectsThroughTheExtrinsicOfItsTime) {
  std::mt19937_64 rng(32);
  DriftingState s;
  randomise(s, rng);
  const double dt_s = -0.8;
  VertexStereoExtrinsic then(4, s.rate.extrinsicAfter(s.extrinsic.estimate(), dt_s));
  EdgeProjectSecondary constant(kCamera);
  constant.setVertex(0, &s.pose);
  constant.setVertex(1, &s.point);
  constant.setVertex(2, &then);
  for (double t : {dt_s, 0.0}) {
    EdgeProjectSecondaryDrifting drifting(kCamera, t);
    drifting.setVertex(0, &s.pose);
    drifting.setVertex(1, &s.point);
    drifting.setVertex(2, &s.extrinsic);
    drifting.setVertex(3, &s.rate);
    constant.setVertex(2, t == 0.0 ? &s.extrinsic : &then);
    Eigen::Vector2d fromDrifting, fromConstant;
    drifting.computeResidual(fromDrifting);
    constant.computeResidual(fromConstant);
    EXPECT_LT((fromDrifting - fromConstant).norm(), 1e-9) << "dt " << t;
  }
  // A rate of 10 mrad/s in pitch over 0.8 s moves the pixel by ~f * 8 mrad.
  Eigen::Vector2d still, moved;
  EdgeProjectSecondaryDrifting drifting(kCamera, dt_s);
  drifting.setVertex(0, &s.pose);
  drifting.setVertex(1, &s.point);
  drifting.setVertex(2, &s.extrinsic);
  drifting.setVertex(3, &s.rate);
  drifting.computeResidual(moved);
  s.rate.setEstimateVector(Vector6::Zero());
  drifting.computeResidual(still);
  EXPECT_GT((moved - still).norm(), 1.0);
}

TEST(ExtrinsicRateEdges, GraphFileRoundTripKeepsTheRate) {
  std::mt19937_64 rng(33);
  DriftingState s;
  randomise(s, rng);
  Graph graph;
  auto* pose = graph.addVertex(std::make_unique<VertexPose>(0, s.pose.cameraFromWorld()));
  auto* point = graph.addVertex(std::make_unique<VertexPoint3>(1, s.point.estimate()));
  auto* extrinsic = graph.addVertex(std::make_unique<VertexStereoExtrinsic>(2, s.extrinsic.estimate()));
  auto* rate = graph.addVertex(std::make_unique<VertexExtrinsicRate>(3, s.rate.estimate()));
  auto edge = std::make_unique<EdgeProjectSecondaryDrifting>(kCamera, -0.6);
  edge->setVertex(0, pose);
  edge->setVertex(1, point);
  edge->setVertex(2, extrinsic);
  edge->setVertex(3, rate);
  edge->setMeasurement(Eigen::Vector2d(610.0, 455.0));
  graph.addEdge(std::move(edge));
  auto prior = std::make_unique<EdgeExtrinsicRatePrior>();
  prior->setVertex(0, rate);
  prior->setInformation(Eigen::Matrix<double, 6, 6>::Identity() * 1e4);
  graph.addEdge(std::move(prior));

  std::stringstream file;
  saveGraph(graph, file);
  EXPECT_NE(file.str().find(EdgeProjectSecondaryDrifting::kTypeTag), std::string::npos);
  EXPECT_NE(file.str().find(VertexExtrinsicRate::kTypeTag), std::string::npos);
  registerEdgeTypes();
  Graph loaded = loadGraph(file, "extrinsic rate graph");
  EXPECT_DOUBLE_EQ(loaded.cost(), graph.cost());
  EXPECT_GT(graph.cost(), 0.0);
}

}  // namespace
}  // namespace lrsvo::test
