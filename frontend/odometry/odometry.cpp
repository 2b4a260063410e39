#include "lrsvo/frontend/odometry/odometry.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

// Streams of the run's seed, each indexed by frame: the initialisation that
// starts at a frame, and the MLESAC pose of a frame.
constexpr std::uint64_t kInitializerStream = 0x696e6974, kPoseStream = 0x706f7365;  // "init", "pose"

int baseObservationCount(const FrameObservations& frame) {
  int count = 0;
  for (const Observation& observation : frame.observations) count += observation.camera == 0;
  return count;
}

FrameObservations withSecondary(const FrameObservations& frame, const SecondaryObservations& secondary) {
  if (!secondary) return frame;
  FrameObservations whole = frame;
  const std::vector<Observation> more = secondary();
  whole.observations.insert(whole.observations.end(), more.begin(), more.end());
  return whole;
}

}  // namespace

Odometry::Odometry(Rig rig, OdometryOptions options)
    : rig_(std::move(rig)), options_(std::move(options)), keyframePolicy_(options_.keyframes), window_(rig_, options_) {
  rig_.validate();
  if (rig_.secondaryCount() < 1) throw Error("odometry: the rig needs a secondary camera");
  options_.validate();
  LongRangeInitializer{options_.initializer};  // validates its options now rather than at the first frame
  samplesWanted_ = options_.initializer.frames;
}

std::vector<FrameEstimate> Odometry::process(const FrameObservations& frame, const SecondaryObservations& secondary) {
  return settled(estimate(frame, secondary));
}

std::vector<FrameEstimate> Odometry::settled(std::vector<FrameEstimate> estimates) {
  for (FrameEstimate& e : estimates) {
    if (e.tracked) {
      motion_.add(e.time_s, e.cameraFromWorld.inverse());
    } else if (motion_.known() && e.time_s >= motion_.lastTime() &&
               e.time_s - motion_.lastTime() <= options_.maxPrediction_s) {
      e.predicted = true;
      e.cameraFromWorld = motion_.predict(e.time_s).inverse();
    }
  }
  return estimates;
}

std::vector<FrameEstimate> Odometry::estimate(const FrameObservations& frame, const SecondaryObservations& secondary) {
  const int index = nextFrame_++;
  // Why the map could not pose this frame, for its note.
  std::string unposed;
  if (tracking_) {
    FrameEstimate estimate = track(frame, index, secondary);
    if (estimate.tracked) return {estimate};
    // Lost: this frame starts the next initialisation.
    unposed = "tracking lost: " + poseShortfall(estimate);
  } else if (canRelocalise(frame.time_s)) {
    FrameEstimate estimate = track(frame, index, secondary);
    if (estimate.tracked) return relocalised(std::move(estimate));
    if (estimate.mappedMatches > 0) unposed = "not posed against the lost map: " + poseShortfall(estimate);
  }
  // The initialiser's samples: the first buffered frame, then each frame at
  // least initializationInterval_s after the last sample (a failed attempt
  // gives up the frames before its second sample, which then leads).
  if (pending_.empty()) {
    FrameObservations whole = withSecondary(frame, secondary);
    const StereoStart start = lrsvo::startFromStereo(rig_, whole, options_.stereoStart);
    if (start.usable) {
      FrameEstimate started = startFromStereo(whole, index, start);
      started.note = joinedNotes(unposed, started.note);
      return {started};
    }
    samples_.push_back(0);
    pending_.push_back({std::move(whole), index, std::move(unposed)});
  } else if (frame.time_s - pending_[samples_.back()].observations.time_s >=
             options_.initializationInterval_s - kFrameTimeSlack_s) {
    samples_.push_back(pending_.size());
    pending_.push_back({withSecondary(frame, secondary), index, std::move(unposed)});
  } else {
    pending_.push_back({frame, index, std::move(unposed)});
  }
  if (static_cast<int>(samples_.size()) < samplesWanted_) return {};
  return initialize();
}

std::vector<FrameEstimate> Odometry::finish() { return settled(givePendingUp()); }

std::vector<FrameEstimate> Odometry::givePendingUp() {
  std::vector<FrameEstimate> estimates;
  for (const PendingFrame& pending : pending_) estimates.push_back(untracked(pending));
  if (!estimates.empty()) estimates.front().times.initialize_ms += std::exchange(initializeMsUnreported_, 0.0);
  clearPending();
  samplesWanted_ = options_.initializer.frames;
  return estimates;
}

void Odometry::clearPending() {
  pending_.clear();
  samples_.clear();
}

FrameEstimate Odometry::untracked(const PendingFrame& pending) const {
  FrameEstimate estimate = untracked(pending.observations, pending.index);
  estimate.note = pending.note;
  return estimate;
}

std::string Odometry::poseShortfall(const FrameEstimate& estimate) const {
  return std::to_string(estimate.poseInliers) + " pose inliers of " + std::to_string(estimate.mappedMatches) +
         " mapped matches (" + std::to_string(options_.minPoseInliers) + " needed)";
}

std::string Odometry::joinedNotes(const std::string& first, const std::string& second) {
  if (first.empty()) return second;
  return second.empty() ? first : first + "; " + second;
}

bool Odometry::canRelocalise(double time_s) const {
  return !window_.points().empty() && motion_.known() && time_s - motion_.lastTime() <= options_.relocaliseWithin_s;
}

std::vector<FrameEstimate> Odometry::relocalised(FrameEstimate estimate) {
  std::vector<FrameEstimate> estimates = givePendingUp();
  tracking_ = true;
  estimate.relocalised = true;
  char note[96];
  std::snprintf(note, sizeof note, "relocalised against the map %.2f s after the last measured pose",
                estimate.time_s - motion_.lastTime());
  estimate.note = note;
  estimates.push_back(std::move(estimate));
  return estimates;
}

Eigen::Isometry3d Odometry::segmentPlacement(double time_s) const {
  return motion_.known() ? motion_.predict(time_s) : Eigen::Isometry3d::Identity();
}

std::vector<int> Odometry::takeRejectedTracks() { return std::exchange(rejectedTracks_, {}); }

FrameEstimate Odometry::untracked(const FrameObservations& frame, int index) const {
  FrameEstimate estimate;
  estimate.frame = index;
  estimate.time_s = frame.time_s;
  estimate.observations = baseObservationCount(frame);
  return estimate;
}

bool Odometry::moreSamplesCouldSettleTheScale(const InitializationResult& result) const {
  const double samples = static_cast<double>(samples_.size());
  const double most = static_cast<double>(options_.maxInitializationFrames);
  return result.scaleTooUncertain && samples < most &&
         result.kappaRelativeStd * std::sqrt(samples / most) <= options_.initializer.maxKappaRelativeStd;
}

std::vector<FrameEstimate> Odometry::initialize() {
  const Stopwatch start;
  std::vector<FrameObservations> sampled;
  for (std::size_t position : samples_) sampled.push_back(pending_[position].observations);
  LongRangeInitializerOptions initializerOptions = options_.initializer;
  initializerOptions.frames = static_cast<int>(sampled.size());
  initializerOptions.seed =
      mixSeed(options_.seed, kInitializerStream, static_cast<std::uint64_t>(pending_.front().index));
  const InitializationResult result = LongRangeInitializer(initializerOptions).initialize(rig_, sampled);

  std::vector<FrameEstimate> estimates;
  if (!result.success && moreSamplesCouldSettleTheScale(result)) {
    // This attempt's time is reported with the attempt that settles the start.
    initializeMsUnreported_ += start.milliseconds();
    ++samplesWanted_;
    return estimates;
  }
  if (!result.success) {
    // Give up the frames before the second sample and try again from it,
    // with as many samples as this attempt had.
    const std::size_t givenUp = samples_[1];
    for (std::size_t i = 0; i < givenUp; ++i) {
      estimates.push_back(untracked(pending_[i]));
      estimates.back().note = joinedNotes(estimates.back().note, "initialisation failed: " + result.failure);
    }
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(givenUp));
    samples_.erase(samples_.begin());
    for (std::size_t& position : samples_) position -= givenUp;
    estimates.front().times.initialize_ms = std::exchange(initializeMsUnreported_, 0.0) + start.milliseconds();
    return estimates;
  }
  samplesWanted_ = options_.initializer.frames;

  // The new segment's world is its first camera; place it where the last
  // segment's motion, carried on, puts that camera.
  const Eigen::Isometry3d worldFromSegment = segmentPlacement(pending_.front().observations.time_s);
  const Eigen::Isometry3d segmentFromWorld = worldFromSegment.inverse();
  std::map<int, Eigen::Vector3d> points;
  for (const auto& [track, point] : result.points) points.emplace(track, worldFromSegment * point);
  std::vector<Keyframe> keyframes;
  for (std::size_t i = 0; i < sampled.size(); ++i)
    keyframes.push_back({pending_[samples_[i]].index, result.cameraFromWorld[i] * segmentFromWorld, sampled[i]});
  window_.reset(keyframes, std::move(points), result.extrinsics, result.kappaRelativeStd);
  ++segment_;
  tracking_ = true;
  const double initialize_ms = std::exchange(initializeMsUnreported_, 0.0) + start.milliseconds();

  for (std::size_t i = 0, sample = 0; i < pending_.size(); ++i) {
    const FrameObservations& observations = pending_[i].observations;
    FrameEstimate estimate = untracked(pending_[i]);
    if (sample < samples_.size() && samples_[sample] == i) {
      estimate.tracked = true;
      estimate.keyframe = true;
      estimate.segment = segment_;
      estimate.cameraFromWorld = keyframes[sample++].cameraFromWorld;
      estimate.extrinsics = window_.extrinsicsAt(observations.time_s);
      estimate.windowRmsError_px = result.rmsReprojectionError_px;
      estimate.bundleIterations = result.summary.iterationCount();
    } else {
      Eigen::Isometry3d pose;
      if (estimateFramePose(observations, pending_[i].index, pose, estimate)) {
        estimate.tracked = true;
        estimate.segment = segment_;
        estimate.cameraFromWorld = pose;
        estimate.extrinsics = window_.extrinsicsAt(observations.time_s);
      }
    }
    estimate.mapPoints = static_cast<int>(window_.points().size());
    estimate.windowFrames = static_cast<int>(window_.keyframes().size());
    estimates.push_back(estimate);
  }
  char note[96];
  std::snprintf(note, sizeof note, "long-range start over %zu samples (scale std %.2g %%)", sampled.size(),
                100.0 * result.kappaRelativeStd);
  FrameEstimate& first = estimates[samples_.front()];
  first.note = joinedNotes(first.note, note);
  estimates.back().times.initialize_ms = initialize_ms;
  clearPending();
  return estimates;
}

FrameEstimate Odometry::startFromStereo(const FrameObservations& frame, int index, const StereoStart& start) {
  const Stopwatch begin;
  // The new segment's world is this camera; place it where the last segment's motion, carried on, puts it.
  const Eigen::Isometry3d worldFromSegment = segmentPlacement(frame.time_s);
  std::map<int, Eigen::Vector3d> points;
  for (const auto& [track, point] : start.points) points.emplace(track, worldFromSegment * point);
  const Eigen::Isometry3d cameraFromWorld = worldFromSegment.inverse();
  window_.reset({{index, cameraFromWorld, frame}}, std::move(points), rig_.extrinsics, start.scaleRelativeStd);
  ++segment_;
  tracking_ = true;

  FrameEstimate estimate = untracked(frame, index);
  estimate.tracked = true;
  estimate.keyframe = true;
  estimate.segment = segment_;
  estimate.cameraFromWorld = cameraFromWorld;
  estimate.extrinsics = window_.extrinsicsAt(frame.time_s);
  estimate.mapPoints = static_cast<int>(window_.points().size());
  estimate.windowFrames = 1;
  estimate.times.initialize_ms = begin.milliseconds();
  char note[96];
  std::snprintf(note, sizeof note, "stereo start at a median depth of %.0f baselines (scale std %.2g %%)",
                start.medianDepthOverBaseline, 100.0 * start.scaleRelativeStd);
  estimate.note = note;
  return estimate;
}

bool Odometry::estimateFramePose(const FrameObservations& frame, int index, Eigen::Isometry3d& cameraFromWorld,
                                 FrameEstimate& estimate) {
  std::vector<PoseMatch> matches;
  std::vector<int> tracks;
  const auto& points = window_.points();
  for (const Observation& observation : frame.observations) {
    if (observation.camera != 0) continue;
    auto point = points.find(observation.track);
    if (point == points.end()) continue;
    matches.push_back({point->second, observation.pixel});
    tracks.push_back(observation.track);
  }
  estimate.mappedMatches = static_cast<int>(matches.size());
  PoseEstimatorOptions poseOptions = options_.pose;
  poseOptions.seed = mixSeed(options_.seed, kPoseStream, static_cast<std::uint64_t>(index));
  const PoseEstimate pose = estimatePose(matches, rig_.cameras[0], poseOptions);
  estimate.poseInliers = pose.inlierCount;
  if (!pose.success || pose.inlierCount < options_.minPoseInliers) return false;
  cameraFromWorld = pose.cameraFromWorld;
  // Matches far off the refined pose are wrong tracks: stop using them.
  std::vector<int> rejected;
  const PinholeIntrinsics& intrinsics = rig_.cameras[0].intrinsics;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    const Eigen::Vector3d inCamera = cameraFromWorld * matches[i].point;
    const bool outlier = inCamera.z() <= 0.0 ||
                         (intrinsics.project(inCamera) - matches[i].pixel).norm() > options_.outliers.maxThreshold_px;
    if (outlier) rejected.push_back(tracks[i]);
  }
  window_.removeTracks(rejected);
  rejectedTracks_.insert(rejectedTracks_.end(), rejected.begin(), rejected.end());
  return true;
}

FrameEstimate Odometry::track(const FrameObservations& frame, int index, const SecondaryObservations& secondary) {
  FrameEstimate estimate = untracked(frame, index);
  Stopwatch start;
  Eigen::Isometry3d pose;
  const bool posed = estimateFramePose(frame, index, pose, estimate);
  estimate.times.pose_ms = start.milliseconds();
  if (!posed) {
    tracking_ = false;
    return estimate;
  }
  estimate.tracked = true;
  estimate.segment = segment_;
  const Keyframe& last = window_.keyframes().back();
  if (keyframePolicy_.isKeyframe(last.observations, frame)) {
    estimate.keyframe = true;
    window_.addKeyframe({index, pose, withSecondary(frame, secondary)});
    start.restart();
    window_.triangulateNewTracks();
    estimate.times.triangulate_ms = start.milliseconds();
    start.restart();
    const WindowAdjustment adjustment = window_.adjust();
    window_.retire();
    estimate.times.bundle_ms = start.milliseconds();
    estimate.windowRmsError_px = adjustment.rmsError_px;
    estimate.outlierThreshold_px = adjustment.outlierThreshold_px;
    estimate.bundleIterations = adjustment.summary.iterationCount();
    rejectedTracks_.insert(rejectedTracks_.end(), adjustment.rejectedTracks.begin(), adjustment.rejectedTracks.end());
    pose = window_.keyframes().back().cameraFromWorld;
  }
  estimate.cameraFromWorld = pose;
  estimate.extrinsics = window_.extrinsicsAt(frame.time_s);
  estimate.mapPoints = static_cast<int>(window_.points().size());
  estimate.windowFrames = static_cast<int>(window_.keyframes().size());
  return estimate;
}

}  // namespace lrsvo
