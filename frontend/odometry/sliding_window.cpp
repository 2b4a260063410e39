#include "lrsvo/frontend/odometry/sliding_window.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <utility>

#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/window_outliers.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/marginal_covariance.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo {
namespace {

// How many keyframes' base cameras observe each track.
std::unordered_map<int, int> baseViewCounts(const std::deque<Keyframe>& keyframes) {
  std::unordered_map<int, int> counts;
  for (const Keyframe& keyframe : keyframes)
    for (const Observation& observation : keyframe.observations.observations)
      if (observation.camera == 0) ++counts[observation.track];
  return counts;
}

// The relative variance of the scale the held views carry, after an
// adjustment that held it with a prior of `priorVariance`. The window's
// marginal counts every observation in it, but each keyframe stays in the
// window for windowSize adjustments: only 1 / windowSize of the information
// it adds over the prior is new.
double carriedScaleVariance(BundleGraph& bundle, const Bounds* enforced, double priorVariance, int windowSize,
                            int threads) {
  const VertexScale* scale = bundle.heldViewScale();
  double windowVariance = priorVariance;
  try {
    windowVariance = marginalCovariance(bundle.graph(), {scale}, bundle.scaleGaugeCoordinates(enforced), threads)(0, 0);
  } catch (const Error&) {
    return priorVariance;  // s held, or its information singular: nothing learnt
  }
  windowVariance /= scale->kappa() * scale->kappa();
  const double added = std::max(0.0, 1.0 / windowVariance - 1.0 / priorVariance);
  return 1.0 / (1.0 / priorVariance + added / windowSize);
}

}  // namespace

SlidingWindow::SlidingWindow(const Rig& rig, const OdometryOptions& options) : rig_(rig), options_(options) {}

void SlidingWindow::reset(std::vector<Keyframe> keyframes, std::map<int, Eigen::Vector3d> points,
                          std::vector<Vector6> extrinsics, double scaleRelativeStd) {
  scaleVariance_ = scaleRelativeStd * scaleRelativeStd;
  keyframes_.assign(std::make_move_iterator(keyframes.begin()), std::make_move_iterator(keyframes.end()));
  anchors_.clear();
  points_ = std::move(points);
  extrinsics_ = std::move(extrinsics);
  if (options_.extrinsicMode == ExtrinsicMode::kRigid) extrinsics_ = rig_.extrinsics;
  rates_.assign(extrinsics_.size(), Vector6::Zero());
  extrinsicTime_s_ = keyframes_.empty() ? 0.0 : keyframes_.back().observations.time_s;
  retire();
}

void SlidingWindow::addKeyframe(Keyframe keyframe) { keyframes_.push_back(std::move(keyframe)); }

SlidingWindow::Vector6 SlidingWindow::extrinsicAt(int camera, double time_s) const {
  const Vector6 s = extrinsicAfter(extrinsics_[camera - 1], rates_[camera - 1], time_s - extrinsicTime_s_);
  // Moved on at its rate, S may not leave the box a bounded window keeps it in.
  return options_.extrinsicMode == ExtrinsicMode::kBounded ? rig_.clampToBox(s, camera) : s;
}

std::vector<SlidingWindow::Vector6> SlidingWindow::extrinsicsAt(double time_s) const {
  std::vector<Vector6> values;
  for (int k = 1; k <= static_cast<int>(extrinsics_.size()); ++k) values.push_back(extrinsicAt(k, time_s));
  return values;
}

Eigen::Isometry3d SlidingWindow::cameraFromWorld(const Eigen::Isometry3d& baseFromWorld, int camera,
                                                 double time_s) const {
  if (camera == 0) return baseFromWorld;
  return secondaryFromBase(extrinsicAt(camera, time_s)) * baseFromWorld;
}

int SlidingWindow::triangulateNewTracks() {
  // Per track: every view, and the base camera's alone.
  std::unordered_map<int, std::vector<TriangulationView>> views, baseViews;
  const std::unordered_map<int, int> counts = baseViewCounts(keyframes_);
  for (const Keyframe& keyframe : keyframes_) {
    std::vector<Eigen::Isometry3d> cameras;  // [k]: this keyframe's camera poses, through S at its time
    for (int k = 0; k <= rig_.secondaryCount(); ++k)
      cameras.push_back(cameraFromWorld(keyframe.cameraFromWorld, k, keyframe.observations.time_s));
    for (const Observation& observation : keyframe.observations.observations) {
      if (points_.count(observation.track)) continue;
      auto count = counts.find(observation.track);
      if (count == counts.end() || count->second < options_.minTriangulationViews) continue;
      const TriangulationView view{cameras[observation.camera], rig_.cameras[observation.camera].intrinsics,
                                   observation.pixel};
      views[observation.track].push_back(view);
      if (observation.camera == 0) baseViews[observation.track].push_back(view);
    }
  }
  int added = 0;
  for (const auto& [track, trackViews] : views) {
    TriangulationResult result = triangulate(trackViews, options_.triangulation);
    // The secondary rays go through the estimated S: while S lags a fast
    // deformation they disagree with the base views, and the track would go
    // unmapped. The base camera's own views still place it.
    if (!result.valid && trackViews.size() > baseViews[track].size())
      result = triangulate(baseViews[track], options_.triangulation);
    if (!result.valid) continue;
    points_[track] = result.point;
    ++added;
  }
  return added;
}

SolverSummary SlidingWindow::solve(BundleGraph& bundle, const Bounds& bounds) const {
  const SolverOptions& solver = options_.solver;
  switch (options_.extrinsicMode) {
    case ExtrinsicMode::kBounded:
      return optimizeWithBounds(bundle.graph(), solver, bounds, options_.constraintMethod, options_.constraintSettings);
    case ExtrinsicMode::kFree:
    case ExtrinsicMode::kRigid: break;
  }
  return Optimizer(solver).optimize(bundle.graph());
}

SparseMap SlidingWindow::windowMap() const {
  // Points seen by one keyframe only are left out: one view (and a short
  // stereo baseline) cannot place them; they stay in the map for tracking.
  const std::unordered_map<int, int> counts = baseViewCounts(keyframes_);
  SparseMap map;
  for (const Keyframe& keyframe : keyframes_) map.cameraFromWorld.push_back(keyframe.cameraFromWorld);
  for (const auto& [track, point] : points_) {
    auto count = counts.find(track);
    if (count != counts.end() && count->second >= 2) map.points.emplace(track, point);
  }
  return map;
}

void SlidingWindow::addToBundle(BundleGraph& bundle, const WindowFrame& frame) const {
  // S is estimated at the newest keyframe's time; with a rate, older
  // keyframes see it as it was then.
  const std::vector<Vector6> start = extrinsicsAt(frame.referenceTime_s);
  for (int k = 1; k <= rig_.secondaryCount(); ++k) {
    bundle.addExtrinsic(k, start[k - 1], extrinsicFixed());
    if (drifting())
      bundle.addExtrinsicRate(k, rates_[k - 1], options_.extrinsicRateSigma * rig_.tolerance, frame.referenceTime_s);
  }
  for (std::size_t i = 0; i < keyframes_.size(); ++i)
    bundle.addObservations(static_cast<int>(i), keyframes_[i].observations);
  if (!anchors_.empty()) bundle.addHeldViewScale(std::sqrt(frame.scalePriorVariance));
  for (const Keyframe& anchor : anchors_) bundle.addHeldView(anchor.cameraFromWorld, frame.origin, anchor.observations);
}

void SlidingWindow::writeBack(BundleGraph& bundle, const Bounds& bounds, const WindowFrame& frame) {
  const SparseMap solved = bundle.map();
  for (std::size_t i = 0; i < keyframes_.size(); ++i) keyframes_[i].cameraFromWorld = solved.cameraFromWorld[i];
  for (const auto& [track, point] : solved.points) points_[track] = point;
  extrinsics_ = bundle.extrinsics();
  extrinsicTime_s_ = frame.referenceTime_s;
  for (int k = 1; drifting() && k <= rig_.secondaryCount(); ++k) rates_[k - 1] = bundle.extrinsicRate(k)->estimate();
  if (anchors_.empty()) return;
  const bool bounded = options_.extrinsicMode == ExtrinsicMode::kBounded;
  scaleVariance_ = carriedScaleVariance(bundle, bounded ? &bounds : nullptr, frame.scalePriorVariance,
                                        options_.windowSize, options_.solver.threads);
  const double heldScale = bundle.heldViewScale()->kappa();
  for (Keyframe& anchor : anchors_) {
    const Eigen::Vector3d centre =
        frame.origin + heldScale * (anchor.cameraFromWorld.inverse().translation() - frame.origin);
    anchor.cameraFromWorld.translation() = -(anchor.cameraFromWorld.linear() * centre);
  }
}

int SlidingWindow::removeOutliers(const WindowOutliers& outliers) {
  int removed = 0;
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    auto& observations = keyframes_[i].observations.observations;
    const auto before = observations.size();
    std::erase_if(observations, [&](const Observation& o) { return outliers.condemns(static_cast<int>(i), o); });
    removed += static_cast<int>(before - observations.size());
  }
  for (int track : outliers.rejectedTracks) points_.erase(track);
  for (Keyframe& anchor : anchors_)
    std::erase_if(anchor.observations.observations,
                  [&](const Observation& o) { return outliers.rejectedTracks.count(o.track); });
  return removed;
}

WindowAdjustment SlidingWindow::adjust() {
  WindowFrame frame;
  frame.referenceTime_s = keyframes_.back().observations.time_s;
  // Held views scale about the oldest keyframe's centre, which is held too.
  frame.origin = keyframes_.front().cameraFromWorld.inverse().translation();
  frame.scalePriorVariance = scaleVariance_ + options_.scaleDriftPerKeyframe * options_.scaleDriftPerKeyframe;
  BundleGraph bundle(rig_, windowMap(), std::min<int>(options_.fixedPoses, static_cast<int>(keyframes_.size())),
                     options_.bundle);
  addToBundle(bundle, frame);

  WindowAdjustment adjustment;
  const Bounds bounds = bundle.extrinsicBounds();
  adjustment.summary = solve(bundle, bounds);
  adjustment.rmsError_px = bundle.rmsReprojectionError_px();
  writeBack(bundle, bounds, frame);

  const WindowOutliers outliers = findWindowOutliers(bundle.projectionErrors(), static_cast<int>(rig_.cameras.size()),
                                                     options_.outliers, adjustment.summary.converged());
  adjustment.outlierThreshold_px = outliers.thresholds_px[0];
  adjustment.removedObservations = removeOutliers(outliers);
  adjustment.rejectedTracks.assign(outliers.rejectedTracks.begin(), outliers.rejectedTracks.end());
  return adjustment;
}

void SlidingWindow::retire() {
  const auto windowSize = static_cast<std::size_t>(options_.windowSize);
  if (keyframes_.size() <= windowSize) return;
  while (keyframes_.size() > windowSize) {
    anchors_.push_back(std::move(keyframes_.front()));
    keyframes_.pop_front();
  }
  while (anchors_.size() > static_cast<std::size_t>(options_.anchorKeyframes)) anchors_.pop_front();
  const std::unordered_map<int, int> counts = baseViewCounts(keyframes_);
  std::erase_if(points_, [&](const auto& entry) { return !counts.count(entry.first); });
}

void SlidingWindow::removeTracks(const std::vector<int>& tracks) {
  const std::set<int> gone(tracks.begin(), tracks.end());
  for (int track : gone) points_.erase(track);
  for (auto* frames : {&anchors_, &keyframes_})
    for (Keyframe& keyframe : *frames)
      std::erase_if(keyframe.observations.observations, [&](const Observation& o) { return gone.count(o.track); });
}

double SlidingWindow::scaleRelativeStd() const { return std::sqrt(scaleVariance_); }

}  // namespace lrsvo
