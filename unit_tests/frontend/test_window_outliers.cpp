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
