#include <gtest/gtest.h>

#include <vector>

#include "lrsvo/frontend/odometry/window_outliers.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

ProjectionError errorOf(int keyframe, int camera, int track, double error_px) {
  ProjectionError error;
  error.frame = keyframe;
  error.observation.camera = camera;
  error.observation.track = track;
  error.error_px = error_px;
  return error;
}

// Every error of a camera equal to e: the Rayleigh median estimate gives
// sigma = e / sqrt(2 ln 2), so the 4-sigma threshold is 3.397 e (within 0.5-4 px).
constexpr double kFourSigmaPerMedian = 3.3972;

TEST(WindowOutliers, BaseOutlierCondemnsItsTrackSecondaryOutlierOnlyItsObservation) {
  std::vector<ProjectionError> errors;
  for (int track = 0; track < 100; ++track) {
    errors.push_back(errorOf(0, 0, track, 0.3));
    errors.push_back(errorOf(1, 1, track, 1.0));
  }
  errors.push_back(errorOf(2, 0, 7, 2.0));  // base: above 4 sigma of 0.3 px errors
  errors.push_back(errorOf(2, 1, 8, 2.0));  // secondary: inside 4 sigma of 1 px errors
  errors.push_back(errorOf(3, 1, 9, 5.0));  // secondary: outside, and past 4 px
  const WindowOutliers outliers = findWindowOutliers(errors, 2, OutlierTestOptions{}, true);

  ASSERT_EQ(outliers.thresholds_px.size(), 2u);
  EXPECT_NEAR(outliers.thresholds_px[0], kFourSigmaPerMedian * 0.3, 1e-3);
  EXPECT_NEAR(outliers.thresholds_px[1], kFourSigmaPerMedian * 1.0, 1e-3);
  EXPECT_EQ(outliers.rejectedTracks, (std::set<int>{7}));
  EXPECT_EQ(outliers.secondaryOutliers, (std::set<std::pair<int, int>>{{3, 9}}));
}

// 100 tracks seen by both cameras of a stereo rig in 10 keyframes, every
// error quietError_px but those of keyframe 9, loudError_px.
std::vector<ProjectionError> windowWithOneLoudKeyframe(double quietError_px, double loudError_px) {
  std::vector<ProjectionError> errors;
  for (int keyframe = 0; keyframe < 10; ++keyframe)
    for (int track = 0; track < 100; ++track)
      for (int camera = 0; camera < 2; ++camera)
        errors.push_back(errorOf(keyframe, camera, track, keyframe == 9 ? loudError_px : quietError_px));
  return errors;
}

std::set<std::pair<int, int>> secondaryObservationsOf(int keyframe, int tracks) {
  std::set<std::pair<int, int>> observations;
  for (int track = 0; track < tracks; ++track) observations.insert({keyframe, track});
  return observations;
}

TEST(WindowOutliers, AKeyframeOffAsAWholeLosesItsStereoNotItsTracks) {
  // Keyframe 9's errors of 0.6 px all pass the window's threshold (the 0.5 px
  // floor: its median is 0.1 px), so the window's test would condemn every
  // track. Its base image is held to 4 sigma of its own 0.6 px, 2.04 px: a
  // track 3 px off there still goes, and its secondary observations go.
  std::vector<ProjectionError> errors = windowWithOneLoudKeyframe(0.1, 0.6);
  errors.push_back(errorOf(9, 0, 100, 3.0));
  const WindowOutliers outliers = findWindowOutliers(errors, 2, OutlierTestOptions{}, true);

  EXPECT_EQ(outliers.thresholds_px, (std::vector<double>{0.5, 0.5}));
  ASSERT_EQ(outliers.offKeyframes.size(), 1u);
  EXPECT_NEAR(outliers.offKeyframes.at(9), kFourSigmaPerMedian * 0.6, 1e-3);
  EXPECT_EQ(outliers.rejectedTracks, (std::set<int>{100}));
  EXPECT_EQ(outliers.secondaryOutliers, secondaryObservationsOf(9, 100));
}

// Keyframe 9's errors are 0.3 px but for its first `past` base tracks,
// 0.8 px, past the window's 0.5 px threshold.
WindowOutliers outliersWithKeyframe9Past(int past) {
  std::vector<ProjectionError> errors = windowWithOneLoudKeyframe(0.1, 0.3);
  for (ProjectionError& error : errors)
    if (error.frame == 9 && error.observation.camera == 0 && error.observation.track < past) error.error_px = 0.8;
  return findWindowOutliers(errors, 2, OutlierTestOptions{}, true);
}

TEST(WindowOutliers, HalfOfAKeyframesErrorsPastTheThresholdAreEachCondemned) {
  const WindowOutliers outliers = outliersWithKeyframe9Past(50);
  EXPECT_TRUE(outliers.offKeyframes.empty());
  EXPECT_EQ(outliers.rejectedTracks.size(), 50u);
  EXPECT_TRUE(outliers.secondaryOutliers.empty());
}

TEST(WindowOutliers, MoreThanHalfOfAKeyframesErrorsPastTheThresholdIsOffAsAWhole) {
  // Its median error is then 0.8 px, and its own 4 sigma 2.72 px.
  const WindowOutliers outliers = outliersWithKeyframe9Past(51);
  ASSERT_EQ(outliers.offKeyframes.size(), 1u);
  EXPECT_NEAR(outliers.offKeyframes.at(9), kFourSigmaPerMedian * 0.8, 1e-3);
  EXPECT_TRUE(outliers.rejectedTracks.empty());
  EXPECT_EQ(outliers.secondaryOutliers, secondaryObservationsOf(9, 100));
}

TEST(WindowOutliers, AKeyframeWithFewErrorsIsNeverOffAsAWhole) {
  // Keyframe 9 keeps 29 of its observations, one fewer than an image needs to
  // estimate its own noise: the window's threshold condemns them all.
  std::vector<ProjectionError> errors = windowWithOneLoudKeyframe(0.1, 0.6);
  std::erase_if(errors, [](const ProjectionError& e) { return e.frame == 9 && e.observation.track >= 29; });
  const WindowOutliers outliers = findWindowOutliers(errors, 2, OutlierTestOptions{}, true);
  EXPECT_TRUE(outliers.offKeyframes.empty());
  EXPECT_EQ(outliers.rejectedTracks.size(), 29u);

  const WindowOutliers fewerNeeded = findWindowOutliers(errors, 2, {.minImageErrors = 29}, true);
  EXPECT_EQ(fewerNeeded.offKeyframes.size(), 1u);
  EXPECT_TRUE(fewerNeeded.rejectedTracks.empty());
}

TEST(WindowOutliers, AMonocularWindowHasNoStereoPairToBlame) {
  std::vector<ProjectionError> errors = windowWithOneLoudKeyframe(0.1, 0.6);
  std::erase_if(errors, [](const ProjectionError& e) { return e.observation.camera != 0; });
  const WindowOutliers outliers = findWindowOutliers(errors, 1, OutlierTestOptions{}, true);
  EXPECT_TRUE(outliers.offKeyframes.empty());
  EXPECT_EQ(outliers.rejectedTracks.size(), 100u);
}

TEST(WindowOutliers, AnUnconvergedSolveThatWouldCondemnManyTracksFallsBackToTheLargestThreshold) {
  // 30 of 100 base tracks at 2 px against a median of 0.3 px: the noise test
  // condemns 30 %, more than the 20 % an unconverged solve is trusted with.
  std::vector<ProjectionError> errors;
  for (int track = 0; track < 100; ++track) errors.push_back(errorOf(0, 0, track, track < 30 ? 2.0 : 0.3));
  const OutlierTestOptions options;

  const WindowOutliers converged = findWindowOutliers(errors, 1, options, true);
  EXPECT_EQ(converged.rejectedTracks.size(), 30u);

  const WindowOutliers unconverged = findWindowOutliers(errors, 1, options, false);
  EXPECT_EQ(unconverged.thresholds_px, std::vector<double>{options.maxThreshold_px});
  EXPECT_TRUE(unconverged.rejectedTracks.empty());
}

TEST(WindowOutliers, AnUnconvergedSolveKeepsTheNoiseTestWhenItCondemnsFewTracks) {
  std::vector<ProjectionError> errors;
  for (int track = 0; track < 100; ++track) errors.push_back(errorOf(0, 0, track, track < 5 ? 2.0 : 0.3));
  const WindowOutliers outliers = findWindowOutliers(errors, 1, OutlierTestOptions{}, false);
  EXPECT_EQ(outliers.rejectedTracks.size(), 5u);
}

TEST(WindowOutliers, ACameraOutsideTheRigIsAnError) {
  const std::vector<ProjectionError> errors = {errorOf(0, 2, 1, 0.5)};
  EXPECT_THROW(findWindowOutliers(errors, 2, OutlierTestOptions{}, true), Error);
  EXPECT_THROW(findWindowOutliers({}, 0, OutlierTestOptions{}, true), Error);
}

}  // namespace
}  // namespace lrsvo
