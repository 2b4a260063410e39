#include "lrsvo/frontend/odometry/rigid_stereo_initializer.h"

#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "lrsvo/frontend/odometry/stereo_start.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

constexpr std::uint64_t kPoseStream = 0x706f7365;  // "pose": MLESAC of frame k

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

// Adds the unmapped tracks of frame `frame` that its stereo pairs place, through the calibrated extrinsics.
void triangulateStereo(SparseMap& map, const Rig& rig, const FrameObservations& observations, int frame,
                       const TriangulationOptions& options) {
  map.points.merge(triangulateAcrossRig(rig, map.cameraFromWorld[frame], observations, options, map.points));
}

void validate(const RigidStereoInitializerOptions& o) {
  if (o.frames < 2) throw Error("rigid stereo initialiser: needs at least 2 frames, got " + std::to_string(o.frames));
  if (o.minPoints < 4) throw Error("rigid stereo initialiser: minPoints must be at least 4 (P3P and a check)");
  o.solver.validate();
}

}  // namespace

RigidStereoInitializer::RigidStereoInitializer(RigidStereoInitializerOptions options) : options_(std::move(options)) {
  validate(options_);
}

InitializationResult RigidStereoInitializer::initialize(const Rig& rig,
                                                        const std::vector<FrameObservations>& frames) const {
  rig.validate();
  if (rig.secondaryCount() < 1) throw Error("rigid stereo initialiser: the rig needs a secondary camera");
  const RigidStereoInitializerOptions& o = options_;
  InitializationResult result;
  result.extrinsics = rig.extrinsics;
  if (static_cast<int>(frames.size()) < o.frames) {
    result.failure =
        "rigid stereo: " + std::to_string(frames.size()) + " frames given, " + std::to_string(o.frames) + " needed";
    return result;
  }

  SparseMap map;
  map.cameraFromWorld = {Eigen::Isometry3d::Identity()};
  triangulateStereo(map, rig, frames[0], 0, o.triangulation);
  std::string failure;
  if (static_cast<int>(map.points.size()) < o.minPoints)
    failure = "frame 0: " + std::to_string(map.points.size()) + " valid stereo triangulations, need " +
              std::to_string(o.minPoints);

  for (int k = 1; k < o.frames && failure.empty(); ++k) {
    std::vector<PoseMatch> matches;
    for (const Observation& observation : frames[k].observations) {
      auto point = map.points.find(observation.track);
      if (observation.camera == 0 && point != map.points.end()) matches.push_back({point->second, observation.pixel});
    }
    if (static_cast<int>(matches.size()) < o.minPoints) {
      failure = "frame " + std::to_string(k) + ": sees " + std::to_string(matches.size()) + " mapped points, need " +
                std::to_string(o.minPoints);
      break;
    }
    PoseEstimatorOptions poseOptions = o.pose;
    poseOptions.seed = mixSeed(o.seed, kPoseStream, static_cast<std::uint64_t>(k));
    const PoseEstimate pose = estimatePose(matches, rig.cameras[0], poseOptions);
    if (!pose.success) {
      failure = "frame " + std::to_string(k) + ": " + pose.failure;
      break;
    }
    map.cameraFromWorld.push_back(pose.cameraFromWorld);
    triangulateStereo(map, rig, frames[k], k, o.triangulation);

    BundleGraph bundle(rig, map, 1, o.bundle);
    for (int camera = 1; camera <= rig.secondaryCount(); ++camera)
      bundle.addExtrinsic(camera, rig.extrinsics[camera - 1], true);
    for (int i = 0; i <= k; ++i) bundle.addObservations(i, frames[i]);
    result.summary = Optimizer(o.solver).optimize(bundle.graph());
    result.rmsReprojectionError_px = bundle.rmsReprojectionError_px();
    map = bundle.map();
  }
  if (failure.empty() && !(result.rmsReprojectionError_px <= o.maxRmsReprojectionError_px))
    failure = "RMS reprojection error " + format("%.3g", result.rmsReprojectionError_px) + " px exceeds " +
              format("%.3g", o.maxRmsReprojectionError_px) + " px (is the rig deformed?)";
  result.cameraFromWorld = std::move(map.cameraFromWorld);
  result.points = std::move(map.points);
  result.success = failure.empty();
  if (!result.success) result.failure = "rigid stereo: " + failure;
  return result;
}

}  // namespace lrsvo
