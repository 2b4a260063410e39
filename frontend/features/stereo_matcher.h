#pragma once

#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/features/klt.h"
#include "lrsvo/frontend/features/undistortion.h"
#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

// Matching across the rig inside a loosened epipolar band: the rig flexes, so
// the true match may sit a few pixels off the epipolar line of the extrinsic
// the band is centred on (the calibration, or the odometry's estimate of S).
struct StereoMatcherOptions {
  double bandWidth_px = 8.0;  // accepted distance either side of that epipolar line
  double minDepth_m = 20.0;   // nearest depth searched (the largest disparity)
  double maxDepth_m = std::numeric_limits<double>::infinity();
  // KLT refinement; its forward-backward check is the left-right consistency
  // check, looser than in time (two cameras' images differ more than two frames').
  KltOptions klt{.forwardBackward_px = 1.0};
  int searchLevel = 1;          // pyramid level of the coarse correlation search along the band
  int searchPatch_px = 9;       // side of the correlation patch at that level
  double minCorrelation = 0.6;  // zero-mean normalised cross-correlation of the coarse match
};

// A base feature found in a secondary camera: raw (distorted) and undistorted pixel.
struct StereoMatch {
  int track = -1;
  cv::Point2f raw;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

// Finds base-camera features in one secondary camera. A feature is looked for
// along the segment of its epipolar line between the projections of its ray at
// minDepth and maxDepth, within the band across it: a coarse correlation search
// on a pyramid level, then KLT to subpixel precision, kept only when it lands
// inside the band and range and tracks back onto the base feature. A track
// matched last frame starts from last frame's offset instead (cheaper, and it
// keeps following the same secondary point); it falls back to the search when
// that fails. A track the search did not find is not searched for again (the
// next frame shows nearly the same view): it stays a base-only track.
class StereoMatcher {
 public:
  // The band starts centred on the calibration, bandWidth_px wide.
  StereoMatcher(const Rig& rig, int camera, const std::vector<LensDistortion>& distortion,
                const StereoMatcherOptions& options);
  // Centres the band on the epipolar lines of extrinsic `s` (this camera's),
  // bandWidth_px plus `widening_px` either side.
  void centreOn(const VertexStereoExtrinsic::Vector6& s, double widening_px = 0.0);
  // How far, at most over the image and the depth range, an extrinsic inside
  // the rig's tolerance box moves a match across the calibrated epipolar
  // line: the widening a band centred on the calibration needs to hold the
  // match of any rig inside its bounds.
  double toleranceSpread_px() const { return toleranceSpread_px_; }
  // `raw` and `undistorted` are the base features' pixels, one per id.
  std::vector<StereoMatch> match(const KltImage& base, const KltImage& secondary, const std::vector<int>& ids,
                                 const std::vector<cv::Point2f>& raw, const std::vector<Eigen::Vector2d>& undistorted);
  // Forgets last frame's matches.
  void reset() {
    previousOffset_.clear();
    searchedInVain_.clear();
  }

 private:
  // The searched part of a base pixel's epipolar line in the undistorted secondary image.
  struct Segment {
    Eigen::Vector2d start, direction;  // start at minDepth (clipped to the image), unit direction
    double length = 0.0;
    bool valid = false;
  };
  Segment segmentOf(const Eigen::Vector2d& basePixel) const;
  // Worst across-line shift of the tolerance box's extrinsics (toleranceSpread_px()).
  double spreadOfToleranceBox(const Rig& rig, int camera) const;
  bool inBand(const Segment& segment, const Eigen::Vector2d& pixel) const;
  // The best correlating raw position along the band, if any correlates well enough.
  bool search(const KltImage& base, const KltImage& secondary, const cv::Point2f& baseRaw, const Segment& segment,
              cv::Point2f& found) const;

  Camera base_, secondary_;
  Eigen::Matrix3d rotation_;  // R_s of the extrinsic the band is centred on
  Eigen::Vector3d centre_;    // c
  double band_px_ = 0.0;      // half-width of the band
  double toleranceSpread_px_ = 0.0;
  Undistorter undistorter_;
  Eigen::Vector2d undistortedLow_, undistortedHigh_;  // the box holding the undistorted image
  StereoMatcherOptions options_;
  std::unordered_map<int, cv::Point2f> previousOffset_;  // track -> raw secondary minus raw base pixel
  std::unordered_set<int> searchedInVain_;               // tracks not found in this camera
};

}  // namespace lrsvo
