#include "lrsvo/frontend/odometry/window_outliers.h"

#include <algorithm>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

using ImageKey = std::pair<int, int>;  // (keyframe, camera)

ImageKey imageOf(const ProjectionError& error) { return {error.frame, error.observation.camera}; }

void classify(const std::vector<ProjectionError>& errors, WindowOutliers& outliers) {
  outliers.rejectedTracks.clear();
  outliers.secondaryOutliers.clear();
  for (const ProjectionError& error : errors) {
    if (error.error_px <= outliers.imageThresholds_px.at(imageOf(error))) continue;
    if (error.observation.camera == 0)
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
  std::map<ImageKey, std::vector<double>> errorsByImage;
  std::set<int> baseTracks;
  for (const ProjectionError& error : errors) {
    const int camera = error.observation.camera;
    if (camera < 0 || camera >= cameraCount)
      throw Error("findWindowOutliers: an error of camera " + std::to_string(camera) + " in a rig of " +
                  std::to_string(cameraCount));
    errorsByCamera[static_cast<std::size_t>(camera)].push_back(error.error_px);
    errorsByImage[imageOf(error)].push_back(error.error_px);
    if (camera == 0) baseTracks.insert(error.observation.track);
  }
  WindowOutliers outliers;
  for (const std::vector<double>& cameraErrors : errorsByCamera)
    outliers.thresholds_px.push_back(outlierThreshold_px(cameraErrors, options));
  for (const auto& [image, imageErrors] : errorsByImage) {
    double threshold = outliers.thresholds_px[static_cast<std::size_t>(image.second)];
    if (static_cast<int>(imageErrors.size()) >= options.minImageErrors)
      threshold = std::max(threshold, outlierThreshold_px(imageErrors, options));
    outliers.imageThresholds_px[image] = threshold;
  }
  classify(errors, outliers);
  if (!solveConverged &&
      static_cast<double>(outliers.rejectedTracks.size()) > options.maxRejectedTrackFraction * baseTracks.size()) {
    outliers.thresholds_px.assign(outliers.thresholds_px.size(), options.maxThreshold_px);
    for (auto& [image, threshold] : outliers.imageThresholds_px) threshold = options.maxThreshold_px;
    classify(errors, outliers);
  }
  return outliers;
}

}  // namespace lrsvo
