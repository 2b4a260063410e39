#include "lrsvo/frontend/odometry/window_outliers.h"

#include <algorithm>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// Whether more than `fraction` of an image's errors pass `threshold_px`.
bool mostlyPast(const std::vector<double>& errors_px, double threshold_px, double fraction) {
  const auto past = std::count_if(errors_px.begin(), errors_px.end(), [&](double e) { return e > threshold_px; });
  return static_cast<double>(past) > fraction * static_cast<double>(errors_px.size());
}

void classify(const std::vector<ProjectionError>& errors, WindowOutliers& outliers) {
  outliers.rejectedTracks.clear();
  outliers.secondaryOutliers.clear();
  for (const ProjectionError& error : errors) {
    const int camera = error.observation.camera;
    const auto off = outliers.offKeyframes.find(error.frame);
    if (off != outliers.offKeyframes.end()) {
      if (camera != 0)
        outliers.secondaryOutliers.insert({error.frame, error.observation.track});
      else if (error.error_px > off->second)
        outliers.rejectedTracks.insert(error.observation.track);
      continue;
    }
    if (error.error_px <= outliers.thresholds_px[static_cast<std::size_t>(camera)]) continue;
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
  validate(options);
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
    for (const auto& [keyframe, baseErrors] : baseErrorsByKeyframe)
      if (static_cast<int>(baseErrors.size()) >= options.minImageErrors &&
          mostlyPast(baseErrors, outliers.thresholds_px[0], options.maxRejectedTrackFraction))
        outliers.offKeyframes[keyframe] = std::max(outliers.thresholds_px[0], outlierThreshold_px(baseErrors, options));
  classify(errors, outliers);
  if (!solveConverged &&
      static_cast<double>(outliers.rejectedTracks.size()) > options.maxRejectedTrackFraction * baseTracks.size()) {
    outliers.thresholds_px.assign(outliers.thresholds_px.size(), options.maxThreshold_px);
    outliers.offKeyframes.clear();
    classify(errors, outliers);
  }
  return outliers;
}

}  // namespace lrsvo
