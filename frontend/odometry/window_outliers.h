#pragma once

#include <map>
#include <set>
#include <utility>
#include <vector>

#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/outlier_threshold.h"

namespace lrsvo {

// The observations a window adjustment condemns, from its reprojection errors.
struct WindowOutliers {
  std::vector<double> thresholds_px;  // per camera over the window, index 0 the base camera
  // Keyframes off as a whole, each with the threshold its base image's own
  // errors give: its secondary observations go, its tracks are held to that.
  std::map<int, double> offKeyframes;
  std::set<int> rejectedTracks;                     // a base-camera outlier condemns its track
  std::set<std::pair<int, int>> secondaryOutliers;  // (keyframe, track): a secondary outlier, that observation only

  // Whether keyframe `keyframe`'s observation goes: its track is rejected, or
  // it is a secondary outlier.
  bool condemns(int keyframe, const Observation& observation) const {
    return rejectedTracks.count(observation.track) ||
           (observation.camera != 0 && secondaryOutliers.count({keyframe, observation.track}));
  }
};

// Finds the outliers among a window's errors. Each camera's threshold comes
// from its own errors over the window (outlierThreshold_px; a secondary
// camera's include how well S follows the rig). A base-camera outlier is a
// wrong temporal match or a corner that is no fixed point (a crown's outline
// sliding over the ground behind it), so its whole track goes; a secondary
// one is a wrong stereo match.
//
// A keyframe whose base image is off as a whole, more than half of its
// errors (at least options.minImageErrors of them) past the base camera's
// threshold, is a stereo pair the window's one S misses: the rig jolted at
// that frame, and the frame's pose splits the miss between its cameras, so
// every observation of the image is off alike. The test's premise, outliers
// a minority of the errors it judges (the median that sets the threshold
// assumes no more), cannot hold for tracks there, and the window's test would
// condemn most of them at once. Its secondary observations go instead (the
// next adjustment fits its pose to the base image alone), and its base image
// is held to the threshold its own errors give. Up to half, each error past
// the threshold condemns its track as usual.
//
// When the solve did not converge and the test would condemn more than
// options.maxRejectedTrackFraction of the window's tracks, the solve is
// suspect rather than the tracks: options.maxThreshold_px applies to every
// observation instead.
WindowOutliers findWindowOutliers(const std::vector<ProjectionError>& errors, int cameraCount,
                                  const OutlierTestOptions& options, bool solveConverged);

}  // namespace lrsvo
