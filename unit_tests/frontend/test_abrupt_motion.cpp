// Tracking through abrupt image motion: the whole image's shift by phase
// correlation, and the feature tracker that falls back on it when its tracks'
// own predictions fail (a gust), matches brightness after an exposure step,
// and finds its tracks again by descriptor alignment after a break (a yaw
// step rotating the image, an unusable image in between).
#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "lrsvo/frontend/features/descriptor_alignment.h"
#include "lrsvo/frontend/features/feature_tracker.h"
#include "lrsvo/frontend/features/klt.h"

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

// The view of viewMovedBy(canvas, 0, 0) rotated by `angle_deg` about its
// centre, and the map from a pixel of that view to the same scene point in it.
struct RotatedView {
  cv::Mat image;
  cv::Matx23d fromUnrotated;  // p -> fromUnrotated * (p, 1)
  cv::Point2f map(const cv::Point2f& p) const {
    const cv::Vec3d h(p.x, p.y, 1.0);
    const cv::Vec2d q = fromUnrotated * h;
    return {static_cast<float>(q[0]), static_cast<float>(q[1])};
  }
};
RotatedView rotatedView(const cv::Mat& canvas, double angle_deg) {
  const cv::Rect view(200, 250, 640, 480);
  const cv::Point2f centre(view.x + view.width / 2.0f, view.y + view.height / 2.0f);
  cv::Mat rotated;
  const cv::Mat onCanvas = cv::getRotationMatrix2D(centre, angle_deg, 1.0);
  cv::warpAffine(canvas, rotated, onCanvas, canvas.size(), cv::INTER_LINEAR);
  // The rotation about the view's centre is the same map in view pixels.
  const cv::Mat inView = cv::getRotationMatrix2D(cv::Point2f(view.width / 2.0f, view.height / 2.0f), angle_deg, 1.0);
  return {rotated(view).clone(), cv::Matx23d(inView)};
}

// A 30 deg rotation of the view (a yaw step of a nadir camera): the homography
// from ORB matches moves every pixel of the central region to where the
// rotation puts it. Each inlier's keypoint is found to about a pixel at the
// finest level (coarser at higher levels); a homography fitted to hundreds of
// them errs by a small fraction of that, so 1.5 px bounds it with room.
TEST(DescriptorAlignment, RecoversARotationOfTheImage) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 11);
  const DescriptorAlignmentOptions options;
  const cv::Mat before = viewMovedBy(canvas, 0, 0);
  const RotatedView after = rotatedView(canvas, 30.0);
  const ImageAlignment alignment =
      alignByDescriptors(describeImage(before, options), describeImage(after.image, options), options);
  ASSERT_TRUE(alignment.found);
  EXPECT_GE(alignment.inliers, options.minInliers);
  std::vector<cv::Point2f> grid;
  for (float y = 140.0f; y <= 340.0f; y += 50.0f)
    for (float x = 220.0f; x <= 420.0f; x += 50.0f) grid.emplace_back(x, y);
  const std::vector<cv::Point2f> moved = transformedPixels(alignment.homography, grid);
  for (std::size_t i = 0; i < grid.size(); ++i) EXPECT_LT(cv::norm(moved[i] - after.map(grid[i])), 1.5) << grid[i];
}

// Two images with nothing in common give no alignment.
TEST(DescriptorAlignment, FindsNothingBetweenUnrelatedImages) {
  const DescriptorAlignmentOptions options;
  const ImageAlignment alignment =
      alignByDescriptors(describeImage(viewMovedBy(multiScaleCanvas(1100, 800, 12), 0, 0), options),
                         describeImage(viewMovedBy(multiScaleCanvas(1100, 800, 13), 0, 0), options), options);
  EXPECT_FALSE(alignment.found);
}

// Where the scene moved each old track (by `toView`), and how many of them
// stay a KLT window inside the image.
struct Expected {
  std::map<int, cv::Point2f> pixel;
  int inside = 0;
};
template <typename Map>
Expected expectedAfter(const std::vector<Track>& tracks, const Map& toView, const KltOptions& klt) {
  Expected expected;
  const float margin = static_cast<float>(klt.window_px);
  for (const Track& t : tracks) {
    const cv::Point2f p = toView(t.pixel);
    expected.pixel[t.id] = p;
    expected.inside += p.x >= margin && p.y >= margin && p.x < 640.0f - margin && p.y < 480.0f - margin;
  }
  return expected;
}

// The tracks found again after a break keep their ids and land where the
// scene point is: KLT converges to a fraction of a pixel on this texture, and
// forwardBackward_px (0.5 px) bounds what it accepts.
void expectRevivedInPlace(const Expected& expected, const std::vector<Track>& tracks, int revived, double minFraction) {
  int found = 0;
  for (const Track& t : tracks) {
    const auto e = expected.pixel.find(t.id);
    if (e == expected.pixel.end()) continue;
    ++found;
    EXPECT_LT(cv::norm(t.pixel - e->second), 0.5 + 1e-3) << "track " << t.id;
  }
  EXPECT_GE(revived, minFraction * expected.inside);
  EXPECT_GE(found, revived);
}

// A yaw step of 30 deg within a frame rotates the image: neither the tracks'
// own motion nor the image's shift predicts them, and KLT's translation-only
// model fails on patches rotated that much. The descriptor alignment finds
// them again, in the same frame, under their ids.
TEST(FeatureTracker, FindsItsTracksAgainAfterAYawStep) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 14);
  FeatureTrackerOptions options;
  FeatureTracker tracker(options);
  tracker.track(makeKltImage(viewMovedBy(canvas, 0, 0), options.klt), 0.0);
  const std::vector<Track> before = tracker.tracks();
  const RotatedView after = rotatedView(canvas, 30.0);
  const auto expected = expectedAfter(
      before, [&](const cv::Point2f& p) { return after.map(p); }, options.klt);
  tracker.track(makeKltImage(after.image, options.klt), 0.1);
  const TrackerStatistics& statistics = tracker.lastStatistics();
  EXPECT_GT(statistics.revived, 0);
  expectRevivedInPlace(expected, tracker.tracks(), statistics.revived, 0.8);
}

// An image with nothing of the scene (a dark frame, a cloud) breaks every
// track; the next view of the scene finds the tracks of the last one before
// the break again, not the ones born on the unusable image.
TEST(FeatureTracker, FindsItsTracksAgainAfterAnUnusableImage) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 15);
  FeatureTrackerOptions options;
  FeatureTracker tracker(options);
  tracker.track(makeKltImage(viewMovedBy(canvas, 0, 0), options.klt), 0.0);
  tracker.track(makeKltImage(viewMovedBy(canvas, 3, 1), options.klt), 0.1);
  const std::vector<Track> before = tracker.tracks();
  tracker.track(makeKltImage(viewMovedBy(multiScaleCanvas(1100, 800, 16), 0, 0), options.klt), 0.2);
  EXPECT_LT(tracker.lastStatistics().tracked, 0.1 * static_cast<double>(before.size()));
  const cv::Point2f shift(9.0f, 60.0f);  // from the second view to the one after the break
  const auto expected = expectedAfter(
      before, [&](const cv::Point2f& p) { return p + shift; }, options.klt);
  tracker.track(makeKltImage(viewMovedBy(canvas, 12, 61), options.klt), 0.3);
  expectRevivedInPlace(expected, tracker.tracks(), tracker.lastStatistics().revived, 0.8);
}

// The 640x480 view of a wide canvas whose content is moved by dx (0-1300 px)
// along x from the view at (1300, 160).
cv::Mat viewAlongStrip(const cv::Mat& canvas, int dx) { return canvas(cv::Rect(1300 - dx, 160, 640, 480)).clone(); }

// The images of a camera whose view moves `step_px` along x every 0.1 s,
// from time 0: the tracker's tracks after the image at `last_s`.
std::vector<Track> trackAlongStrip(FeatureTracker& tracker, const cv::Mat& canvas, double last_s, int step_px,
                                   const KltOptions& klt) {
  for (int k = 0; 0.1 * k <= last_s + 1e-9; ++k)
    tracker.track(makeKltImage(viewAlongStrip(canvas, step_px * k), klt), 0.1 * k);
  return tracker.tracks();
}

// 2.5 s without a usable view (a cloud, then a hole in the stream): the first
// image after it has moved 500 px, and shares a strip of 140 px (22 %) with
// the last one before, which the motion before the break, carried on, predicts
// in view: the tracks in that strip are found again, under their ids. (With a
// fixed 2 s search the break would have been given up.)
TEST(FeatureTracker, FindsItsTracksAgainAfterSecondsWithoutAView) {
  const cv::Mat canvas = multiScaleCanvas(2000, 800, 20);
  FeatureTrackerOptions options;
  FeatureTracker tracker(options);
  const std::vector<Track> before = trackAlongStrip(tracker, canvas, 0.4, 20, options.klt);
  const auto expected = expectedAfter(
      before, [&](const cv::Point2f& p) { return p + cv::Point2f(500.0f, 0.0f); }, options.klt);
  ASSERT_GE(expected.inside, options.alignment.minInliers);
  tracker.track(makeKltImage(viewMovedBy(multiScaleCanvas(1100, 800, 23), 0, 0), options.klt), 0.5);
  EXPECT_EQ(tracker.lastStatistics().revived, 0);
  tracker.track(makeKltImage(viewAlongStrip(canvas, 80 + 500), options.klt), 2.9);
  expectRevivedInPlace(expected, tracker.tracks(), tracker.lastStatistics().revived, 0.8);
}

// Once the motion before a break, carried on, leaves less than
// minReviveOverlap of the last image before it in view, its tracks are no
// longer looked for, even in an image that does show them (the camera
// stopped): at 400 px/s, 1.7 s after the break the prediction is 680 px on,
// past the 640 px image. The same image 1.2 s after (480 px predicted: 25 %
// in view) has them found again.
TEST(FeatureTracker, StopsLookingOnceTheImageBeforeTheBreakIsPredictedOutOfView) {
  const cv::Mat canvas = multiScaleCanvas(2000, 800, 21);
  for (const double after_s : {1.2, 1.7}) {
    FeatureTrackerOptions options;
    FeatureTracker tracker(options);
    trackAlongStrip(tracker, canvas, 0.4, 40, options.klt);
    tracker.track(makeKltImage(viewMovedBy(multiScaleCanvas(1100, 800, 22), 0, 0), options.klt), 0.5);
    tracker.track(makeKltImage(viewAlongStrip(canvas, 160), options.klt), 0.4 + after_s);
    if (after_s < 1.5) {
      EXPECT_GE(tracker.lastStatistics().revived, options.alignment.minInliers);
    } else {
      EXPECT_EQ(tracker.lastStatistics().revived, 0);
    }
  }
}

// Past reviveWithin_s the tracks before a break are no longer looked for.
TEST(FeatureTracker, ForgetsABreakAfterReviveWithin) {
  const cv::Mat canvas = multiScaleCanvas(1100, 800, 17);
  FeatureTrackerOptions options;
  options.reviveWithin_s = 0.15;
  FeatureTracker tracker(options);
  tracker.track(makeKltImage(viewMovedBy(canvas, 0, 0), options.klt), 0.0);
  tracker.track(makeKltImage(viewMovedBy(multiScaleCanvas(1100, 800, 18), 0, 0), options.klt), 0.1);
  tracker.track(makeKltImage(viewMovedBy(canvas, 5, 5), options.klt), 0.3);
  EXPECT_EQ(tracker.lastStatistics().revived, 0);
}

}  // namespace
}  // namespace lrsvo
