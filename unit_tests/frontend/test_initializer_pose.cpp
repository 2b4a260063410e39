#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/pose_estimator.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {
namespace {

Camera testCamera() {
  Camera camera;
  camera.intrinsics = {1200.0, 1200.0, 640.0, 480.0};
  camera.width = 1280;
  camera.height = 960;
  return camera;
}

struct PoseScene {
  std::vector<PoseMatch> matches;
  std::vector<bool> outlier;
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
};

// 200 world points on bumpy ground 60-70 m below a tilted camera; a fraction
// of the matches replaced by pixels drawn uniformly over the image.
PoseScene makeScene(double outlierFraction, double noise_px, std::uint64_t seed) {
  const Camera camera = testCamera();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  PoseScene scene;
  Eigen::Isometry3d worldFromCamera = Eigen::Isometry3d::Identity();
  worldFromCamera.linear() = expSO3(Eigen::Vector3d(std::numbers::pi + 0.05, 0.04, 0.3));  // looking down
  worldFromCamera.translation() = Eigen::Vector3d(12.0, -4.0, 65.0);
  scene.cameraFromWorld = worldFromCamera.inverse();
  while (scene.matches.size() < 200) {
    const Eigen::Vector2d pixel(unit(rng) * camera.width, unit(rng) * camera.height);
    const double depth = 60.0 + 10.0 * unit(rng);
    const Eigen::Vector3d inCamera((pixel.x() - 640.0) / 1200.0 * depth, (pixel.y() - 480.0) / 1200.0 * depth, depth);
    PoseMatch match{worldFromCamera * inCamera, pixel + Eigen::Vector2d(noise(rng), noise(rng))};
    const bool outlier = unit(rng) < outlierFraction;
    if (outlier) match.pixel = Eigen::Vector2d(unit(rng) * camera.width, unit(rng) * camera.height);
    scene.matches.push_back(match);
    scene.outlier.push_back(outlier);
  }
  return scene;
}

double positionError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.inverse().translation() - b.inverse().translation()).norm();
}

TEST(InitializerPose, MlesacScoreMatchesHandComputation) {
  // No EM step: gamma stays at 1/2. Errors 0 px, 2 px and behind the camera,
  // sigma 1 px, a 100 px^2 image (uniform density 0.01).
  const std::vector<double> squared = {0.0, 4.0, std::numeric_limits<double>::infinity()};
  double gamma = 0.0;
  std::vector<double> posterior;
  const double score = mlesacScore(squared, 1.0, 100.0, 0, &gamma, &posterior);
  const double g0 = 1.0 / (2.0 * std::numbers::pi), g2 = std::exp(-2.0) / (2.0 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(gamma, 0.5);
  EXPECT_NEAR(score, -std::log(0.5 * g0 + 0.005) - std::log(0.5 * g2 + 0.005) - std::log(0.005), 1e-12);
  EXPECT_NEAR(posterior[0], 0.5 * g0 / (0.5 * g0 + 0.005), 1e-12);
  EXPECT_NEAR(posterior[1], 0.5 * g2 / (0.5 * g2 + 0.005), 1e-12);
  EXPECT_EQ(posterior[2], 0.0);
  // EM converges to gamma = mean posterior inlier probability (a fixed point).
  mlesacScore(squared, 1.0, 100.0, 100, &gamma, nullptr);
  const double meanPosterior =
      (gamma * g0 / (gamma * g0 + (1.0 - gamma) * 0.01) + gamma * g2 / (gamma * g2 + (1.0 - gamma) * 0.01)) / 3.0;
  EXPECT_NEAR(gamma, meanPosterior, 1e-9);
  EXPECT_GT(gamma, 0.5);  // the 0 px error is almost surely an inlier, the 2 px one more likely than not
}

TEST(InitializerPose, RecoversExactPoseWithoutOutliers) {
  const PoseScene scene = makeScene(0.0, 0.0, 1);
  const PoseEstimate estimate = estimatePose(scene.matches, testCamera());
  ASSERT_TRUE(estimate.success) << estimate.failure;
  EXPECT_LT(positionError(estimate.cameraFromWorld, scene.cameraFromWorld), 1e-6);
  EXPECT_EQ(estimate.inlierCount, 200);
}

TEST(InitializerPose, RecoversPoseAndFlagsThirtyPercentOutliers) {
  const PoseScene scene = makeScene(0.3, 1.0, 2);
  const PoseEstimate estimate = estimatePose(scene.matches, testCamera(), {.seed = 5});
  ASSERT_TRUE(estimate.success) << estimate.failure;
  // 1 px over ~140 inliers at 65 m, f = 1200: centimetres to a few decimetres along the view axis.
  EXPECT_LT(positionError(estimate.cameraFromWorld, scene.cameraFromWorld), 0.3);
  EXPECT_LT(Eigen::AngleAxisd(estimate.cameraFromWorld.linear() * scene.cameraFromWorld.linear().transpose()).angle(),
            2e-3);
  int wrongFlags = 0, outliers = 0;
  for (std::size_t i = 0; i < scene.matches.size(); ++i) {
    wrongFlags += estimate.inliers[i] == scene.outlier[i] ? 1 : 0;
    outliers += scene.outlier[i] ? 1 : 0;
  }
  EXPECT_EQ(wrongFlags, 0);
  EXPECT_EQ(estimate.inlierCount, 200 - outliers);
  EXPECT_NEAR(estimate.inlierFraction, 1.0 - outliers / 200.0, 0.02);
  EXPECT_LT(estimate.hypotheses, 1000);  // the adaptive count stopped early
}

TEST(InitializerPose, SameSeedSameResult) {
  const PoseScene scene = makeScene(0.3, 1.0, 3);
  const PoseEstimate first = estimatePose(scene.matches, testCamera(), {.seed = 11});
  const PoseEstimate second = estimatePose(scene.matches, testCamera(), {.seed = 11});
  EXPECT_TRUE(first.cameraFromWorld.isApprox(second.cameraFromWorld, 0.0));
  EXPECT_EQ(first.inliers, second.inliers);
  EXPECT_EQ(first.hypotheses, second.hypotheses);
}

TEST(InitializerPose, ReportsTooFewMatches) {
  PoseScene scene = makeScene(0.0, 0.0, 4);
  scene.matches.resize(3);
  const PoseEstimate estimate = estimatePose(scene.matches, testCamera());
  EXPECT_FALSE(estimate.success);
  EXPECT_NE(estimate.failure.find("3 2D-3D matches"), std::string::npos) << estimate.failure;
}

}  // namespace
}  // namespace lrsvo
