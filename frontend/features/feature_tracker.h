#pragma once

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "lrsvo/frontend/features/descriptor_alignment.h"
#include "lrsvo/frontend/features/feature_detector.h"
#include "lrsvo/frontend/features/klt.h"

namespace lrsvo {

// How the base camera's features are followed from frame to frame. The mode
// follows the detector: "klt" (pyramidal Lucas-Kanade, forward-backward
// checked) for detectors without descriptors (gftt, fast); "descriptor"
// (ORB Hamming matching near the predicted position, ratio test) for orb.
struct FeatureTrackerOptions {
  DetectorOptions detector;
  int targetFeatures = 300;  // top up with new features when fewer survive
  // "klt": new features are detected only once this fraction of targetFeatures
  // is missing. Detection scans the image and tracking only the tracks, so
  // topping up the few lost every frame would cost more than the tracking.
  double topUpFraction = 0.1;
  KltOptions klt;
  // "klt": when fewer than this fraction of the tracks follow from their
  // predicted positions, the whole image's shift (globalShift) predicts them
  // instead, and whichever prediction keeps more tracks wins.
  double realignBelowFraction = 0.5;
  // "klt": when the mean grey level changes by more than this fraction
  // between frames (an exposure step), the previous image is brought to the
  // new one's brightness before tracking (KLT assumes it constant).
  double brightnessTolerance = 0.05;
  // "klt": a break is a frame where even the shift keeps fewer than
  // realignBelowFraction of the tracks (a yaw step rotates the image, an
  // unusable image in between, a gap in the stream). The tracks of the last
  // image before it are then looked for again, in that frame and each later
  // one, for as long as the image motion before the break, carried on at its
  // rate in pixels per second, leaves at least minReviveOverlap of that image
  // in view (and for at most reviveWithin_s): that image is aligned to the new
  // one by ORB matches (descriptor_alignment.h), warped onto it, and KLT finds
  // the lost tracks there, under their old ids, so the odometry's map still
  // knows them.
  DescriptorAlignmentOptions alignment;
  double minReviveOverlap = 0.1;
  double reviveWithin_s = 10.0;
  double descriptorSearch_px = 40.0;  // "descriptor": radius around the predicted position
  double descriptorRatio = 0.8;       // best distance below this times the second best
  int maxHamming = 64;                // "descriptor": worst accepted distance (of 256 bits)
};

// One feature followed in the base camera, at its raw (distorted) pixel.
struct Track {
  int id = -1;
  cv::Point2f pixel;
  int age = 0;  // frames since it was detected (0 = new this frame)
  // How far it moved from the previous frame (zero when new). The next frame
  // looks for it there first: periodic texture (crop rows) makes KLT from
  // zero motion lock onto the wrong row once the flow nears a row period, and
  // a fast flow leaves a descriptor search radius around the old position.
  cv::Point2f motion;
  cv::Mat descriptor;  // one row, "descriptor" mode only
};

struct TrackerStatistics {
  int tracked = 0;         // tracks continued from the previous frame
  int added = 0;           // new tracks detected this frame
  bool realigned = false;  // the tracks were predicted by the whole image's shift
  int revived = 0;         // tracks of the image before a break found again (FeatureTrackerOptions::alignment)
  double track_ms = 0.0;
  double detect_ms = 0.0;
};

// Keeps the tracks of the base camera. Track ids are never reused, not even
// after reset(). Outliers among the tracks are removed from outside with
// drop() (the front end's fundamental-matrix check, the back end's rejects).
class FeatureTracker {
 public:
  explicit FeatureTracker(const FeatureTrackerOptions& options);
  std::string mode() const { return detector_.hasDescriptors() ? "descriptor" : "klt"; }
  // Follows the tracks into the next image (taken at time_s), then tops them up.
  const std::vector<Track>& track(const KltImage& image, double time_s = 0.0);
  const std::vector<Track>& tracks() const { return tracks_; }
  const TrackerStatistics& lastStatistics() const { return statistics_; }
  void drop(const std::vector<int>& ids);
  // Forgets every track (after tracking loss); the next image starts afresh.
  void reset();

 private:
  // Where each track should be in the next image: moved on by its last
  // motion, or a new track by the median motion of the others.
  std::vector<cv::Point2f> predictedPixels() const;
  // `imageMean`: the image's mean grey level. A break keeps the tracks before
  // it in broken_.
  void followByKlt(const KltImage& image, double imageMean);
  // Finds broken_'s tracks again in `image`, taken at time_s
  // (FeatureTrackerOptions::alignment): when the images align, each takes its
  // aligned position or is dropped. Forgets broken_ once the images align, or
  // once its image is predicted out of view or reviveWithin_s has passed.
  void revive(const KltImage& image, double imageMean, double time_s);
  // The previous image, or, after an exposure step, that image brought to the
  // brightness of `next` (FeatureTrackerOptions::brightnessTolerance).
  KltImage previousWithBrightnessOf(const KltImage& next, double nextMean) const;
  void followByDescriptor(const DetectedFeatures& candidates);
  void addNew(DetectedFeatures features, int wanted);

  FeatureTrackerOptions options_;
  FeatureDetector detector_;
  std::vector<Track> tracks_;
  KltImage previous_;
  double previousMean_ = 0.0;  // previous_'s mean grey level ("klt")
  double previousTime_ = 0.0;
  double previousInterval_s_ = 0.0;  // from the image before previous_ to it: the span of the tracks' motion
  // The last image before a break, with its tracks, while they are looked for.
  struct Broken {
    cv::Mat image;
    double mean = 0.0;
    double time_s = 0.0;
    std::vector<Track> tracks;
    int firstNewId = 0;                       // of the tracks born since
    cv::Point2f velocity_px_s;                // the tracks' median motion before the break
    std::optional<DescribedImage> described;  // computed on the first search
  };
  // The fraction of broken's image that its motion, carried on to time_s,
  // leaves inside an image of `imageSize`.
  double predictedOverlap(const Broken& broken, cv::Size imageSize, double time_s) const;
  std::optional<Broken> broken_;
  int nextId_ = 0;
  TrackerStatistics statistics_;
};

}  // namespace lrsvo
