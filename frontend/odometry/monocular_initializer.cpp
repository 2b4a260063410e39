#include "lrsvo/frontend/odometry/monocular_initializer.h"

#include <map>
#include <set>
#include <string>
#include <utility>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

constexpr std::uint64_t kPoseStream = 0x706f7365;  // "pose": MLESAC of frame k

using PixelsByTrack = std::map<int, Eigen::Vector2d>;

std::vector<PixelsByTrack> basePixels(const std::vector<FrameObservations>& frames, int count) {
  std::vector<PixelsByTrack> pixels(count);
  for (int i = 0; i < count; ++i)
    for (const Observation& observation : frames[i].observations)
      if (observation.camera == 0) pixels[i][observation.track] = observation.pixel;
  return pixels;
}

// Triangulates every unmapped track seen in at least `minViews` of the posed
// frames (and in `allowed`, when given) and adds the valid ones to the map.
void triangulateNewTracks(SparseMap& map, const std::vector<PixelsByTrack>& pixels, const PinholeIntrinsics& intrinsics,
                          int minViews, const TriangulationOptions& options, const std::set<int>* allowed) {
  std::map<int, std::vector<TriangulationView>> views;
  for (std::size_t i = 0; i < map.cameraFromWorld.size(); ++i)
    for (const auto& [track, pixel] : pixels[i])
      if (!map.points.count(track) && (!allowed || allowed->count(track)))
        views[track].push_back({map.cameraFromWorld[i], intrinsics, pixel});
  for (const auto& [track, trackViews] : views) {
    if (static_cast<int>(trackViews.size()) < minViews) continue;
    const TriangulationResult point = triangulate(trackViews, options);
    if (point.valid) map.points[track] = point.point;
  }
}

// The graph's pose i is frame order[i]; returns the RMS reprojection error after.
double bundleAdjust(SparseMap& map, const std::vector<int>& order, const Rig& rig,
                    const std::vector<FrameObservations>& frames, const MonocularOptions& options,
                    SolverSummary& summary) {
  BundleGraph bundle(rig, map, 1, options.bundle);
  bundle.holdDistance(0, 1);
  for (std::size_t i = 0; i < map.cameraFromWorld.size(); ++i)
    bundle.addObservations(static_cast<int>(i), frames[order[i]]);
  summary = Optimizer(options.solver).optimize(bundle.graph());
  map = bundle.map();
  return bundle.rmsReprojectionError_px();
}

// The second frame of the two-view pair: the last one that still shares
// pairOverlap of frame 0's tracks.
int pairFrame(const std::vector<PixelsByTrack>& pixels, double pairOverlap) {
  int pair = 1;
  for (std::size_t k = 2; k < pixels.size(); ++k) {
    std::size_t shared = 0;
    for (const auto& [track, pixel] : pixels[0]) shared += pixels[k].count(track);
    if (static_cast<double>(shared) >= pairOverlap * static_cast<double>(pixels[0].size())) pair = static_cast<int>(k);
  }
  return pair;
}

void validate(const MonocularOptions& options) {
  if (options.frames < 2) throw Error("monocular initialiser: needs at least 2 frames");
  if (!(options.initialBaseline > 0.0)) throw Error("monocular initialiser: initialBaseline must be positive");
  if (options.minViews < 2) throw Error("monocular initialiser: a point needs minViews >= 2 views");
  if (!(options.pairOverlap > 0.0 && options.pairOverlap <= 1.0))
    throw Error("monocular initialiser: pairOverlap must lie in (0, 1]");
}

// The map from one motion hypothesis of the pair (frame 0 and frame order[1]):
// its shared inliers triangulated, then every other frame posed and mapped in turn.
MonocularResult mapFromPair(const Rig& rig, const std::vector<FrameObservations>& frames,
                            const MonocularOptions& options, const std::vector<int>& order,
                            const std::vector<PixelsByTrack>& pixels, const TwoViewResult& twoViewPose) {
  MonocularResult result;
  const Camera& camera = rig.cameras[0];
  const std::string pairName = "frames 0-" + std::to_string(order[1]);
  if (!twoViewPose.success) {
    result.failure = "monocular, " + pairName + ": " + twoViewPose.failure;
    return result;
  }
  SparseMap map;
  map.cameraFromWorld = {Eigen::Isometry3d::Identity(), twoViewPose.bFromA()};
  const std::set<int> pairInliers(twoViewPose.inlierTracks.begin(), twoViewPose.inlierTracks.end());
  triangulateNewTracks(map, pixels, camera.intrinsics, 2, options.triangulation, &pairInliers);
  if (static_cast<int>(map.points.size()) < options.minPairPoints) {
    result.failure = "monocular: " + std::to_string(map.points.size()) + " points triangulated from " + pairName +
                     ", need " + std::to_string(options.minPairPoints);
    return result;
  }
  result.rmsReprojectionError_px = bundleAdjust(map, order, rig, frames, options, result.summary);

  for (std::size_t i = 2; i < order.size(); ++i) {
    const int k = order[i];
    std::vector<PoseMatch> matches;
    for (const auto& [track, pixel] : pixels[i]) {
      auto point = map.points.find(track);
      if (point != map.points.end()) matches.push_back({point->second, pixel});
    }
    if (static_cast<int>(matches.size()) < options.minPosePoints) {
      result.failure = "monocular, frame " + std::to_string(k) + ": sees " + std::to_string(matches.size()) +
                       " mapped points, need " + std::to_string(options.minPosePoints);
      return result;
    }
    PoseEstimatorOptions poseOptions = options.pose;
    poseOptions.seed = mixSeed(options.seed, kPoseStream, static_cast<std::uint64_t>(k));
    const PoseEstimate pose = estimatePose(matches, camera, poseOptions);
    if (!pose.success) {
      result.failure = "monocular, frame " + std::to_string(k) + ": " + pose.failure;
      return result;
    }
    map.cameraFromWorld.push_back(pose.cameraFromWorld);
    triangulateNewTracks(map, pixels, camera.intrinsics, options.minViews, options.triangulation, nullptr);
    result.rmsReprojectionError_px = bundleAdjust(map, order, rig, frames, options, result.summary);
  }

  // Back to frame order, in the unit that puts frames 0 and 1 initialBaseline apart.
  result.map.points = std::move(map.points);
  result.map.cameraFromWorld.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) result.map.cameraFromWorld[order[i]] = map.cameraFromWorld[i];
  const auto& poses = result.map.cameraFromWorld;
  result.map.scale(options.initialBaseline /
                   (poses[1].inverse().translation() - poses[0].inverse().translation()).norm());
  result.success = true;
  return result;
}

}  // namespace

std::vector<MonocularResult> buildMonocularMaps(const Rig& rig, const std::vector<FrameObservations>& frames,
                                                const MonocularOptions& options) {
  rig.validate();
  validate(options);
  if (static_cast<int>(frames.size()) < options.frames) {
    MonocularResult tooFew;
    tooFew.failure =
        "monocular: " + std::to_string(frames.size()) + " frames given, " + std::to_string(options.frames) + " needed";
    return {tooFew};
  }
  const std::vector<PixelsByTrack> framePixels = basePixels(frames, options.frames);

  // Frames in the order they are posed: the pair, then the rest from the first.
  const int pair = pairFrame(framePixels, options.pairOverlap);
  std::vector<int> order = {0, pair};
  for (int k = 1; k < options.frames; ++k)
    if (k != pair) order.push_back(k);
  std::vector<PixelsByTrack> pixels;
  for (int k : order) pixels.push_back(framePixels[k]);

  TwoViewOptions twoView = options.twoView;
  twoView.camera = 0;
  twoView.seed = options.seed;
  std::vector<MonocularResult> maps;
  for (const TwoViewResult& motion : twoViewHypotheses(frames[0], frames[pair], rig.cameras[0].intrinsics, twoView))
    maps.push_back(mapFromPair(rig, frames, options, order, pixels, motion));
  return maps;
}

MonocularResult buildMonocularMap(const Rig& rig, const std::vector<FrameObservations>& frames,
                                  const MonocularOptions& options) {
  std::vector<MonocularResult> maps = buildMonocularMaps(rig, frames, options);
  auto best = maps.begin();
  for (auto map = maps.begin(); map != maps.end(); ++map)
    if (map->success && (!best->success || map->rmsReprojectionError_px < best->rmsReprojectionError_px)) best = map;
  return std::move(*best);
}

}  // namespace lrsvo
