#include <random>

#include <gtest/gtest.h>

#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/vertices/so3.h"
#include "test_problems.h"

namespace lrsvo::test {
namespace {

struct StereoState {
  VertexPose pose{0};
  VertexPoint3 point{1};
  VertexStereoExtrinsic extrinsic{2};
  VertexScale scale{3};
  PinholeIntrinsics intrinsics{1670.0, 1660.0, 640.0, 480.0};
};

// A camera ~100 m above a ground point, a deformed 0.7 m rig.
void randomise(StereoState& s, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = expSO3(Eigen::Vector3d(0.2 * n(rng), 0.2 * n(rng), 0.2 * n(rng)));
  pose.translation() = Eigen::Vector3d(5 * n(rng), 5 * n(rng), 100.0 + 10 * n(rng));
  s.pose.setCameraFromWorld(pose);
  const Eigen::Vector3d inCamera(10 * n(rng), 10 * n(rng), 100.0 + 10 * n(rng));
  s.point.setEstimateVector(pose.inverse() * inCamera);
  VertexStereoExtrinsic::Vector6 e;
  e << 0.001 * n(rng), 0.7 + 0.001 * n(rng), 0.001 * n(rng), 0.01 * n(rng), 0.01 * n(rng), 0.01 * n(rng);
  s.extrinsic.setEstimateVector(e);
  s.scale.setEstimateVector(Eigen::Matrix<double, 1, 1>(0.5 + std::abs(n(rng))));
}

TEST(StereoEdges, AnalyticJacobiansMatchNumeric) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    StereoState s;
    randomise(s, rng);
    EdgeProjectBase base(s.intrinsics);
    base.setVertex(0, &s.pose);
    base.setVertex(1, &s.point);
    EXPECT_TRUE(jacobiansMatchNumeric(base, 1e-5, 1e-6));
    EdgeProjectSecondary secondary(SecondaryCamera{1, s.intrinsics});
    secondary.setVertex(0, &s.pose);
    secondary.setVertex(1, &s.point);
    secondary.setVertex(2, &s.extrinsic);
    EXPECT_TRUE(jacobiansMatchNumeric(secondary, 1e-5, 1e-6));
    EdgeProjectSecondaryScaled scaled(SecondaryCamera{1, s.intrinsics});
    scaled.setVertex(0, &s.pose);
    scaled.setVertex(1, &s.point);
    scaled.setVertex(2, &s.extrinsic);
    scaled.setVertex(3, &s.scale);
    EXPECT_TRUE(jacobiansMatchNumeric(scaled, 1e-5, 1e-6));
  }
}

TEST(StereoEdges, SecondaryProjectionMatchesHandComputedRig) {
  // Base camera at the origin looking down +z; secondary 0.7 m along +y, not rotated.
  StereoState s;
  VertexStereoExtrinsic::Vector6 e;
  e << 0.0, 0.7, 0.0, 0.0, 0.0, 0.0;
  s.extrinsic.setEstimateVector(e);
  s.point.setEstimateVector(Eigen::Vector3d(1.0, 2.0, 100.0));
  EdgeProjectSecondary edge(SecondaryCamera{1, s.intrinsics});
  edge.setVertex(0, &s.pose);
  edge.setVertex(1, &s.point);
  edge.setVertex(2, &s.extrinsic);
  Eigen::Vector2d residual;
  edge.computeResidual(residual);
  EXPECT_NEAR(residual.x(), 1670.0 * 1.0 / 100.0 + 640.0, 1e-9);
  EXPECT_NEAR(residual.y(), 1660.0 * (2.0 - 0.7) / 100.0 + 480.0, 1e-9);
  // kappa = 2 halves the baseline seen in the map's unit.
  EdgeProjectSecondaryScaled scaled(SecondaryCamera{1, s.intrinsics});
  scaled.setVertex(0, &s.pose);
  scaled.setVertex(1, &s.point);
  scaled.setVertex(2, &s.extrinsic);
  scaled.setVertex(3, &s.scale);
  s.scale.setEstimateVector(Eigen::Matrix<double, 1, 1>(2.0));
  scaled.computeResidual(residual);
  EXPECT_NEAR(residual.y(), 1660.0 * (2.0 - 0.35) / 100.0 + 480.0, 1e-9);
}

TEST(StereoEdges, NonPositiveKappaGivesNonFiniteCost) {
  StereoState s;
  s.point.setEstimateVector(Eigen::Vector3d(0.0, 0.0, 50.0));
  s.scale.setEstimateVector(Eigen::Matrix<double, 1, 1>(-0.1));
  EdgeProjectSecondaryScaled scaled(SecondaryCamera{1, s.intrinsics});
  scaled.setVertex(0, &s.pose);
  scaled.setVertex(1, &s.point);
  scaled.setVertex(2, &s.extrinsic);
  scaled.setVertex(3, &s.scale);
  EXPECT_FALSE(std::isfinite(scaled.cost()));
}

}  // namespace
}  // namespace lrsvo::test
