#include "lrsvo/frontend/odometry/window_outliers.h"

#include <algorithm>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// Whether `condemned` of `total` tracks is more than the test of an
// unconverged solve is trusted with (OutlierTestOptions::maxRejectedTrackFraction).
bool condemnsTooMany(std::size_t condemned, std::size_t total, const OutlierTestOptions& options) {
  return static_cast<double>(condemned) > options.maxRejectedTrackFraction * static_cast<double>(total);
}

void classify(const std::vector<ProjectionError>& errors, WindowOutliers& outliers) {
  outliers.rejectedTracks.clear();
  outliers.secondaryOutliers.clear();
  for (const ProjectionError& error : errors) {
    const int camera = error.observation.camera;
    const auto off = outliers.offKeyframes.find(error.frame);
    const bool offKeyframe = off != outliers.offKeyframes.end();
    // An off keyframe's secondary observations all go; its base ones face its own threshold.
    const double threshold_px =
        offKeyframe && camera == 0 ? off->second : outliers.thresholds_px[static_cast<std::size_t>(camera)];
    if (!(offKeyframe && camera != 0) && error.error_px <= threshold_px) continue;
    if (camera == 0)
      outliers.rejectedTracks.insert(error.observation.track);
    else
      outliers.secondaryOutliers.insert({error.frame, error.observation.track});
  }
}

}  // namespace

WindowOutliers findWindowOutliers(const std::vector<ProjectionError>& errors, int cameraCount,
                                  const OutlierTestOptions& options, bool solveConverged) {
  if (cameraCount < 1) throw Error("findWindowOutliers: need at least the base camera");
  std::vector<std::vector<double>> errorsByCamera(static_cast<std::size_t>(cameraCount));
  std::map<int, std::vector<double>> baseErrorsByKeyframe;
  std::set<int> baseTracks;
  for (const ProjectionError& error : errors) {
    const int camera = error.observation.camera;
    if (camera < 0 || camera >= cameraCount)
      throw Error("findWindowOutliers: an error of camera " + std::to_string(camera) + " in a rig of " +
                  std::to_string(cameraCount));
    errorsByCamera[static_cast<std::size_t>(camera)].push_back(error.error_px);
    if (camera == 0) {
      baseErrorsByKeyframe[error.frame].push_back(error.error_px);
      baseTracks.insert(error.observation.track);
    }
  }
  WindowOutliers outliers;
  for (const std::vector<double>& cameraErrors : errorsByCamera)
    outliers.thresholds_px.push_back(outlierThreshold_px(cameraErrors, options));
  if (cameraCount > 1)
    for (const auto& [keyframe, baseErrors] : baseErrorsByKeyframe) {
      const auto past =
          std::count_if(baseErrors.begin(), baseErrors.end(), [&](double e) { return e > outliers.thresholds_px[0]; });
      // More than half of the image past the threshold, its median error too: the test takes outliers
      // for a minority of what it judges, so they are not the image's tracks.
      if (static_cast<int>(baseErrors.size()) >= options.minImageErrors &&
          2 * static_cast<std::size_t>(past) > baseErrors.size())
        outliers.offKeyframes[keyframe] = std::max(outliers.thresholds_px[0], outlierThreshold_px(baseErrors, options));
    }
  classify(errors, outliers);
  if (!solveConverged && condemnsTooMany(outliers.rejectedTracks.size(), baseTracks.size(), options)) {
    outliers.thresholds_px.assign(outliers.thresholds_px.size(), options.maxThreshold_px);
    outliers.offKeyframes.clear();
    classify(errors, outliers);
  }
  return outliers;
}

}  // namespace lrsvo
