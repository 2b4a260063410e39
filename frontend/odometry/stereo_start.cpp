#include "lrsvo/frontend/odometry/stereo_start.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "lrsvo/graph/error.h"

namespace lrsvo {

std::map<int, Eigen::Vector3d> triangulateAcrossRig(const Rig& rig, const Eigen::Isometry3d& baseFromWorld,
                                                    const FrameObservations& frame, const TriangulationOptions& options,
                                                    const std::map<int, Eigen::Vector3d>& known) {
  std::map<int, std::vector<TriangulationView>> views;
  std::set<int> seenByBase;
  for (const Observation& observation : frame.observations) {
    if (known.count(observation.track)) continue;
    views[observation.track].push_back({rig.cameraFromWorld(baseFromWorld, observation.camera),
                                        rig.cameras[observation.camera].intrinsics, observation.pixel});
    if (observation.camera == 0) seenByBase.insert(observation.track);
  }
  std::map<int, Eigen::Vector3d> points;
  for (const auto& [track, trackViews] : views) {
    if (!seenByBase.count(track) || trackViews.size() < 2) continue;
    const TriangulationResult point = triangulate(trackViews, options);
    if (point.valid) points.emplace(track, point.point);
  }
  return points;
}

void StereoStartOptions::validate() const {
  if (!(maxDepthOverBaseline >= 0.0)) throw Error("stereo start: maxDepthOverBaseline must be >= 0 (0: never)");
  if (minPoints < 4) throw Error("stereo start: minPoints must be at least 4 (P3P and a check)");
}

StereoStart startFromStereo(const Rig& rig, const FrameObservations& frame, const StereoStartOptions& options) {
  StereoStart start;
  if (options.maxDepthOverBaseline <= 0.0) {
    start.reason = "the stereo start is off";
    return start;
  }
  start.points = triangulateAcrossRig(rig, Eigen::Isometry3d::Identity(), frame, options.triangulation);
  if (start.points.empty()) {
    start.reason = "no stereo point";
    return start;
  }
  // The shortest baseline of the rig: the one that sees depth least well.
  double baseline_m = rig.extrinsics.front().head<3>().norm();
  for (const auto& extrinsic : rig.extrinsics) baseline_m = std::min(baseline_m, extrinsic.head<3>().norm());
  std::vector<double> depths;
  for (const auto& [track, point] : start.points) depths.push_back(point.z());
  auto middle = depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2);
  std::nth_element(depths.begin(), middle, depths.end());
  start.medianDepthOverBaseline = *middle / baseline_m;
  const double rotationTolerance = rig.tolerance.tail<3>().maxCoeff();
  start.scaleRelativeStd = rotationTolerance * start.medianDepthOverBaseline / std::sqrt(3.0);
  char text[160];
  if (static_cast<int>(start.points.size()) < options.minPoints) {
    std::snprintf(text, sizeof text, "%d stereo points, need %d", static_cast<int>(start.points.size()),
                  options.minPoints);
    start.reason = text;
  } else if (start.medianDepthOverBaseline > options.maxDepthOverBaseline) {
    std::snprintf(text, sizeof text, "median depth %.0f baselines, beyond %.0f", start.medianDepthOverBaseline,
                  options.maxDepthOverBaseline);
    start.reason = text;
  }
  start.usable = start.reason.empty();
  return start;
}

}  // namespace lrsvo
