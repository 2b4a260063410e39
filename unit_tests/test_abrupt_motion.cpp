// Tracking through abrupt image motion: the whole image's shift by phase
// correlation, and the feature tracker that falls back on it when its tracks'
// own predictions fail (a gust), or matches brightness after an exposure step.
#include <algorithm>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "frontend/feature_tracker.h"
#include "frontend/klt.h"

namespace lrsvo {
namespace {

// A seeded texture with detail from 2 px to 60 px (blurred noise at three
// scales), like aerial imagery: coarse pyramid levels keep structure too.
cv::Mat multiScaleCanvas(int width, int height, std::uint64_t seed) {
  cv::Mat sum(height, width, CV_32F, cv::Scalar(0));
  cv::RNG rng(seed);
  for (double sigma : {2.0, 8.0, 30.0}) {
    cv::Mat noise(height, width, CV_32F);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
    cv::GaussianBlur(noise, noise, cv::Size(), sigma);
    cv::Scalar mean, spread;
    cv::meanStdDev(noise, mean, spread);
    sum += noise / spread[0];
  }
  cv::Mat image;
  sum.convertTo(image, CV_8U, 25.0, 128.0);
  return image;
}

// The 640x480 view of the canvas whose content is moved by (dx, dy) from the view at (200, 250).
cv::Mat viewMovedBy(const cv::Mat& canvas, int dx, int dy) {
  return canvas(cv::Rect(200 - dx, 250 - dy, 640, 480)).clone();
}

TEST(GlobalShift, RecoversAWholeImageTranslation) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 7);
  const KltOptions options;
  const KltImage from = makeKltImage(viewMovedBy(canvas, 0, 0), options);
  for (const auto& [dx, dy] : {std::pair{180, -45}, std::pair{-120, 130}, std::pair{3, 2}}) {
    const ImageShift found = globalShift(from, makeKltImage(viewMovedBy(canvas, dx, dy), options));
    // Phase correlation is subpixel at the coarsest level (8 px a pixel): within 4 px.
    EXPECT_NEAR(found.shift.x, dx, 4.0) << dx << ", " << dy;
    EXPECT_NEAR(found.shift.y, dy, 4.0) << dx << ", " << dy;
    EXPECT_GT(found.response, 0.1);
  }
}

// Tracks that moved by 3 px a frame suddenly move by 190 px (a roll of 12.75
// deg at f = 834 px): from their predicted positions, 23 px off at the top of
// the three-level pyramid, KLT loses them; from the whole image's shift it
// keeps nearly all.
TEST(FeatureTracker, FollowsAJumpOfHundredsOfPixels) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 8);
  for (const double realignBelow : {0.5, 0.0}) {
    FeatureTrackerOptions options;
    options.realignBelowFraction = realignBelow;
    FeatureTracker tracker(options);
    tracker.track(makeKltImage(viewMovedBy(canvas, 0, 0), options.klt));
    tracker.track(makeKltImage(viewMovedBy(canvas, 3, 0), options.klt));
    const int before = static_cast<int>(tracker.tracks().size());
    tracker.track(makeKltImage(viewMovedBy(canvas, 3, 190), options.klt));
    const TrackerStatistics& statistics = tracker.lastStatistics();
    // Of the tracks, those whose new position is still inside the image (190 of 480 rows leave it).
    const double stayInside = before * (480.0 - 190.0 - 2 * options.detector.border_px) / 480.0;
    if (realignBelow > 0.0) {
      EXPECT_TRUE(statistics.realigned);
      EXPECT_GE(statistics.tracked, 0.8 * stayInside);
    } else {
      EXPECT_FALSE(statistics.realigned);
      EXPECT_LT(statistics.tracked, 0.2 * stayInside);
    }
  }
}

// An exposure step of +30 % between two frames: the previous image is brought
// to the new brightness first, and the tracks go on (without it, KLT keeps
// about three in four).
TEST(FeatureTracker, FollowsAnExposureStep) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 9);
  FeatureTrackerOptions options;
  FeatureTracker tracker(options);
  tracker.track(makeKltImage(viewMovedBy(canvas, 0, 0), options.klt));
  const int before = static_cast<int>(tracker.tracks().size());
  cv::Mat brighter;
  viewMovedBy(canvas, 2, 1).convertTo(brighter, CV_8U, 1.3);
  tracker.track(makeKltImage(brighter, options.klt));
  EXPECT_GE(tracker.lastStatistics().tracked, 0.9 * before);
}

}  // namespace
}  // namespace lrsvo
