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
  std::vector<double> thresholds_px;  // per camera over the whole window, index 0 the base camera
  // Per image, (keyframe, camera): the threshold its observations are held to,
  // never below its camera's over the window.
  std::map<std::pair<int, int>, double> imageThresholds_px;
  std::set<int> rejectedTracks;                     // a base-camera outlier condemns its track
  std::set<std::pair<int, int>> secondaryOutliers;  // (keyframe, track): a secondary outlier, that observation only
};

// Finds the outliers among a window's errors. Each camera's threshold comes
// from its own errors over the window (outlierThreshold_px; a secondary
// camera's include how well S follows the rig); an image whose own errors are
// larger, and that has at least options.minImageErrors of them, is held to the
// threshold they give. The error level differs from image to image: where the
// rig vibrates, the one S a window shares misses a frame's stereo pair, and
// that frame's pose splits the miss between its cameras, so every observation
// of that image is off alike. That says nothing against its tracks. A
// base-camera outlier is a wrong temporal match or a corner that is no fixed
// point (a crown's outline sliding over the ground behind it), so its whole
// track goes; a secondary one is a wrong stereo match. When the solve did not
// converge and the test would condemn more than
// options.maxRejectedTrackFraction of the base camera's tracks, the solve is
// suspect rather than the tracks: options.maxThreshold_px applies to every
// image instead.
WindowOutliers findWindowOutliers(const std::vector<ProjectionError>& errors, int cameraCount,
                                  const OutlierTestOptions& options, bool solveConverged);

}  // namespace lrsvo
