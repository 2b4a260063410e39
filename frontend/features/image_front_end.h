#pragma once

#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/features/feature_tracker.h"
#include "lrsvo/frontend/features/stereo_matcher.h"
#include "lrsvo/frontend/features/undistortion.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

struct ImageFrontEndOptions {
  FeatureTrackerOptions tracker;  // detector name, target feature count, KLT window and levels
  StereoMatcherOptions stereo;    // band width, depth range
  // Frame-to-frame tracks are checked against a RANSAC fundamental matrix on
  // undistorted pixels; gross outliers are dropped here, the rest is the back end's.
  bool fundamentalCheck = true;
  double fundamentalThreshold_px = 1.0;
  std::uint64_t seed = 1;  // the fundamental matrix RANSAC's draws
};

// What the last process() call did, and how long each stage took.
struct FrontEndTimings {
  double detect_ms = 0.0;
  double track_ms = 0.0;      // base pyramid, KLT or descriptor matching, fundamental check
  double stereo_ms = 0.0;     // secondary pyramids and matching (its own undistortion included); 0 when not asked
  double undistort_ms = 0.0;  // base features
  double total_ms = 0.0;
  int tracked = 0;        // tracks continued from the previous frame (after the fundamental check)
  int added = 0;          // new tracks
  int rejected = 0;       // dropped by the fundamental check
  int stereoMatched = 0;  // base tracks found in at least one secondary camera (when matched)
  int realigned = 0;  // 1: the tracks were predicted by the whole image's shift (an abrupt motion); sums count frames
  int revived = 0;    // tracks of the image before a break found again by descriptor alignment
};

// From a rig's images to the observations the odometry consumes: features are
// tracked in the base camera over time and matched into each secondary camera
// inside a loosened epipolar band; positions are undistorted last. Each track
// is observed in camera 0 always and in camera k when matched there.
class ImageFrontEnd {
 public:
  ImageFrontEnd(const Rig& rig, const std::vector<LensDistortion>& distortion, const ImageFrontEndOptions& options);
  // The base camera alone: features tracked in time, all a frame's pose and the
  // keyframe choice need.
  FrameObservations track(const StereoFrame& frame);
  // The last tracked frame's base tracks found in each secondary camera. Stereo
  // matching costs as much as tracking, and the odometry needs it only for the
  // frames it keeps (keyframes, initialisation frames), so it runs on request,
  // once per frame.
  std::vector<Observation> matchAcrossRig();
  // track(frame) with matchAcrossRig() appended.
  FrameObservations process(const StereoFrame& frame);
  // Where stereo matching looks: in each secondary camera, the band
  // (StereoMatcherOptions::bandWidth_px) around the epipolar lines of
  // extrinsics[k - 1], the odometry's current estimate of S. A rig flexing by
  // its whole tolerance moves matches further off the calibrated lines than a
  // band narrow enough to stay unambiguous on periodic texture.
  void centreBandsOn(const std::vector<VertexStereoExtrinsic::Vector6>& extrinsics);
  // Before S is estimated (the start, and after reset()): bands around the
  // calibrated lines, widened to hold the matches of any rig inside its
  // tolerance box (StereoMatcher::toleranceSpread_px).
  void centreBandsOnCalibration();
  // The back end rejected these tracks as outliers: never report them again.
  void dropTracks(const std::vector<int>& trackIds);
  // After tracking loss: forget every track (new ones get fresh ids), and
  // centre the bands on the calibration.
  void reset();
  const FrontEndTimings& lastTimings() const { return timings_; }

 private:
  void checkFrame(const StereoFrame& frame) const;
  void checkImage(int frameIndex, int camera, const cv::Mat& image) const;
  // Drops the continued tracks that break the fundamental matrix; returns how many.
  int rejectOutliers(const std::vector<Track>& tracks, const std::vector<Eigen::Vector2d>& pixels);

  Rig rig_;
  ImageFrontEndOptions options_;
  FeatureTracker tracker_;
  Undistorter baseUndistorter_;
  std::vector<StereoMatcher> matchers_;  // [k - 1]
  KltOptions pyramid_;                   // how every image's pyramid is built
  std::mt19937_64 rng_;
  std::unordered_map<int, Eigen::Vector2d> previousPixel_;  // undistorted base pixel by track, last frame
  FrontEndTimings timings_;
  // The last tracked frame, kept for matchAcrossRig(): its base pyramid, the
  // frame itself (for its secondary images), and its tracks (id, raw and
  // undistorted pixel).
  KltImage base_;
  StereoFrame trackedFrame_;
  std::vector<int> ids_;
  std::vector<cv::Point2f> raw_;
  std::vector<Eigen::Vector2d> pixels_;
  bool matched_ = true;  // matchAcrossRig() already ran for the last frame (or there is none)
};

}  // namespace lrsvo
