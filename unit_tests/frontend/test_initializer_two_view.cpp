#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/two_view.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {
namespace {

const PinholeIntrinsics kIntrinsics{1000.0, 1000.0, 640.0, 480.0};

struct TwoViewScene {
  FrameObservations a, b;
  Eigen::Isometry3d bFromA = Eigen::Isometry3d::Identity();
};

// 200 points 15-40 m in front of camera a, seen by both cameras; camera b
// 2 m away, turned by a few degrees. Pixel noise of `noise_px` per axis.
TwoViewScene makeScene(double noise_px, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> depth(15.0, 40.0), lateral(-0.5, 0.5);
  std::normal_distribution<double> noise(0.0, noise_px);
  TwoViewScene scene;
  scene.bFromA.linear() = expSO3(Eigen::Vector3d(0.03, -0.05, 0.02));
  const Eigen::Vector3d centreB(1.6, 0.3, 1.2);  // |centre| = 2.02 m, in camera a's frame
  scene.bFromA.translation() = -scene.bFromA.linear() * centreB;
  int track = 0;
  while (track < 200) {
    const double z = depth(rng);
    const Eigen::Vector3d point(lateral(rng) * z, lateral(rng) * z, z);
    const Eigen::Vector3d inB = scene.bFromA * point;
    const Eigen::Vector2d pixelB = kIntrinsics.project(inB);
    if (inB.z() <= 0.0 || pixelB.x() < 0 || pixelB.x() > 1280 || pixelB.y() < 0 || pixelB.y() > 960) continue;
    const Eigen::Vector2d pixelA = kIntrinsics.project(point);
    scene.a.observations.push_back({track, 0, pixelA + Eigen::Vector2d(noise(rng), noise(rng))});
    scene.b.observations.push_back({track, 0, pixelB + Eigen::Vector2d(noise(rng), noise(rng))});
    ++track;
  }
  return scene;
}

double rotationError(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

double directionError(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(InitializerTwoView, RecoversRotationAndDirectionOnExactData) {
  const TwoViewScene scene = makeScene(0.0, 3);
  const TwoViewResult result = estimateTwoView(scene.a, scene.b, kIntrinsics);
  ASSERT_TRUE(result.success) << result.failure;
  EXPECT_NEAR(result.translation.norm(), 1.0, 1e-12);
  EXPECT_LT(rotationError(result.rotation, scene.bFromA.linear()), 1e-6);
  EXPECT_LT(directionError(result.translation, scene.bFromA.translation()), 1e-5);
  EXPECT_EQ(result.inlierTracks.size(), 200u);
  EXPECT_EQ(result.correspondences, 200);
  // bFromA scales the unit translation to the requested distance.
  EXPECT_NEAR(result.bFromA(2.5).translation().norm(), 2.5, 1e-12);
}

// Measured over seeds 1-20 (after the refinement): rotation errors 0.4-3.6
// mrad, direction errors 1.7-27 mrad, 180-198 inliers. The direction is the
// weak part: 2 m of baseline over 15-40 m trades off against a rotation of
// the camera. RANSAC's minimal-sample model alone was 3-16 mrad and 28-102 mrad.
TEST(InitializerTwoView, RecoversRotationAndDirectionWithOnePixelNoise) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TwoViewScene scene = makeScene(1.0, seed);
    const TwoViewResult result = estimateTwoView(scene.a, scene.b, kIntrinsics);
    ASSERT_TRUE(result.success) << result.failure;
    EXPECT_LT(rotationError(result.rotation, scene.bFromA.linear()), 5e-3) << "seed " << seed;
    EXPECT_LT(directionError(result.translation, scene.bFromA.translation()), 0.05) << "seed " << seed;
    EXPECT_GT(result.inlierTracks.size(), 170u) << "seed " << seed;
  }
}

TEST(InitializerTwoView, SameSeedSameResult) {
  const TwoViewScene scene = makeScene(1.0, 5);
  const TwoViewResult first = estimateTwoView(scene.a, scene.b, kIntrinsics, {.seed = 9});
  const TwoViewResult second = estimateTwoView(scene.a, scene.b, kIntrinsics, {.seed = 9});
  EXPECT_EQ(first.rotation, second.rotation);
  EXPECT_EQ(first.translation, second.translation);
  EXPECT_EQ(first.inlierTracks, second.inlierTracks);
}

// 200 points of flat ground 60 m below camera a, which looks straight down;
// camera b 6.7 m along a's x axis (the paper's frames 10 apart at 20 m/s),
// turned by a few milliradians. Pixel noise of 0.5 px per axis.
TwoViewScene makeGroundScene(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> lateral(-0.3, 0.3);
  std::normal_distribution<double> noise(0.0, 0.5);
  TwoViewScene scene;
  scene.bFromA.linear() = expSO3(Eigen::Vector3d(0.004, -0.003, 0.002));
  scene.bFromA.translation() = -scene.bFromA.linear() * Eigen::Vector3d(6.7, 0.0, 0.0);
  for (int track = 0; track < 200; ++track) {
    const Eigen::Vector3d point(60.0 * lateral(rng), 60.0 * lateral(rng), 60.0);
    const Eigen::Vector2d pixelA = kIntrinsics.project(point);
    const Eigen::Vector2d pixelB = kIntrinsics.project(scene.bFromA * point);
    scene.a.observations.push_back({track, 0, pixelA + Eigen::Vector2d(noise(rng), noise(rng))});
    scene.b.observations.push_back({track, 0, pixelB + Eigen::Vector2d(noise(rng), noise(rng))});
  }
  return scene;
}

// Whichever motion the essential matrix picks on flat ground, the true one
// is among the hypotheses (the essential matrix's own, or the homography's).
// Measured over seeds 1-5: the twin keeps 25-43 % of the ground in front of
// both cameras, so it is never a hypothesis here.
TEST(InitializerTwoView, FlatGroundHypothesesHoldTheTrueMotion) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TwoViewScene scene = makeGroundScene(seed);
    const std::vector<TwoViewResult> hypotheses = twoViewHypotheses(scene.a, scene.b, kIntrinsics);
    bool hasTrue = false;
    for (const TwoViewResult& motion : hypotheses) {
      ASSERT_TRUE(motion.success) << motion.failure;
      hasTrue |= rotationError(motion.rotation, scene.bFromA.linear()) < 0.01 &&
                 directionError(motion.translation, scene.bFromA.translation()) < 0.1;
    }
    EXPECT_TRUE(hasTrue) << "seed " << seed << ", " << hypotheses.size() << " hypotheses";
  }
}

TEST(InitializerTwoView, ReportsTooFewCorrespondences) {
  TwoViewScene scene = makeScene(0.0, 6);
  scene.a.observations.resize(10);
  const TwoViewResult result = estimateTwoView(scene.a, scene.b, kIntrinsics);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.failure.find("10 shared tracks"), std::string::npos) << result.failure;
}

}  // namespace
}  // namespace lrsvo
