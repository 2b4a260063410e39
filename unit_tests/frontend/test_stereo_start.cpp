#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/stereo_start.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// A frame of the paper's rig (0.7 m baseline) seeing `count` points spread
// over the view at depths around `depth_m` (+-10 %), with 0.3 px of noise.
FrameObservations stereoFrameAt(const Rig& rig, double depth_m, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.3);
  FrameObservations frame;
  const PinholeIntrinsics& k = rig.cameras[0].intrinsics;
  for (int track = 0; track < count; ++track) {
    const double z = depth_m * (1.0 + 0.1 * unit(rng));
    const Eigen::Vector3d point(0.4 * z * unit(rng) * rig.cameras[0].width / k.fx,
                                0.4 * z * unit(rng) * rig.cameras[0].height / k.fy, z);
    for (int camera = 0; camera < 2; ++camera) {
      const Eigen::Vector3d inCamera = rig.cameraFromWorld(Eigen::Isometry3d::Identity(), camera) * point;
      const Eigen::Vector2d pixel = rig.cameras[camera].intrinsics.project(inCamera);
      frame.observations.push_back({track, camera, pixel + Eigen::Vector2d(noise(rng), noise(rng))});
    }
  }
  return frame;
}

// Close range starts from stereo: its points come back at their depths, and
// the scale's uncertainty is the rotation tolerance's (10 mrad) spread of the
// disparities: q (z / b) / sqrt(3), 0.082 at 14 baselines.
TEST(StereoStart, CloseRangeStartsFromStereo) {
  const Rig rig = paperRig();
  const StereoStart start = startFromStereo(rig, stereoFrameAt(rig, 10.0, 80, 1), StereoStartOptions{});
  EXPECT_TRUE(start.usable) << start.reason;
  EXPECT_NEAR(start.medianDepthOverBaseline, 10.0 / 0.7, 0.1 * 10.0 / 0.7);
  EXPECT_NEAR(start.scaleRelativeStd, 0.01 * start.medianDepthOverBaseline / std::sqrt(3.0), 1e-12);
  EXPECT_GE(start.points.size(), 70u);
  for (const auto& [track, point] : start.points) EXPECT_NEAR(point.z(), 10.0, 1.5) << track;
}

TEST(StereoStart, LongRangeOrTooFewPointsDoNot) {
  const Rig rig = paperRig();
  const StereoStart far = startFromStereo(rig, stereoFrameAt(rig, 100.0, 80, 2), StereoStartOptions{});
  EXPECT_FALSE(far.usable);
  EXPECT_NE(far.reason.find("baselines, beyond 40"), std::string::npos) << far.reason;
  const StereoStart few = startFromStereo(rig, stereoFrameAt(rig, 10.0, 12, 3), StereoStartOptions{});
  EXPECT_FALSE(few.usable);
  EXPECT_NE(few.reason.find("need 30"), std::string::npos) << few.reason;
  StereoStartOptions never;
  never.maxDepthOverBaseline = 0.0;
  EXPECT_FALSE(startFromStereo(rig, stereoFrameAt(rig, 10.0, 80, 4), never).usable);
  never.maxDepthOverBaseline = -1.0;
  EXPECT_THROW(never.validate(), Error);
}

}  // namespace
}  // namespace lrsvo
