#pragma once

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "frontend/frame_estimate.h"
#include "frontend/keyframe_policy.h"
#include "frontend/observations.h"
#include "frontend/odometry_options.h"
#include "frontend/rig.h"
#include "frontend/sliding_window.h"

namespace lrsvo {

// The long-range stereo odometry loop (the paper's Fig. 8) over a stream of
// feature observations (from the image front end or the feature simulator):
//  - initialising: frames are buffered until the long-range initialiser has
//    its N frames (one every initializationStep); on success every buffered
//    frame gets a pose and the initialised frames fill the window; on failure
//    the oldest buffered frames are given up (untracked) and it tries again;
//  - tracking: each frame's pose by P3P in MLESAC from base observations of
//    mapped points; a keyframe (KeyframePolicy) joins the sliding window, new
//    tracks seen in >= 3 keyframes are triangulated, the window is adjusted
//    (poses, points, shared S: bounded, free or rigid) and the oldest
//    keyframe retired;
//  - too few pose inliers: tracking is lost; a fresh initialisation starts,
//    and its segment is placed at the last tracked pose.
// The world is the first initialised base camera's frame, in metres.
class Odometry {
 public:
  // Throws lrsvo::Error on an invalid rig or options.
  Odometry(Rig rig, OdometryOptions options);

  // Feeds the next frame; returns the estimates that became known, in frame
  // order: none while initialising, all buffered frames when it succeeds,
  // otherwise this frame's. With `secondary`, `frame` may hold base
  // observations alone: the secondary ones are fetched, at most once, only for
  // a frame that is kept (a keyframe, or a frame the initialiser samples); the
  // estimates are the same as for the whole frame.
  std::vector<FrameEstimate> process(const FrameObservations& frame, const SecondaryObservations& secondary = {});
  // Estimates of frames still buffered at the end of a sequence (untracked).
  std::vector<FrameEstimate> finish();
  // Tracks the odometry rejected since the last call (wrong matches): the
  // image front end should stop tracking them.
  std::vector<int> takeRejectedTracks();

  bool tracking() const { return tracking_; }
  const Rig& rig() const { return rig_; }
  const OdometryOptions& options() const { return options_; }
  const SlidingWindow& window() const { return window_; }

 private:
  std::vector<FrameEstimate> initialize();
  FrameEstimate track(const FrameObservations& frame, int index, const SecondaryObservations& secondary);
  // Pose of a frame from its base observations of mapped points (nullopt-like: success flag).
  bool estimateFramePose(const FrameObservations& frame, int index, Eigen::Isometry3d& cameraFromWorld,
                         FrameEstimate& estimate);
  FrameEstimate untracked(const FrameObservations& frame, int index) const;

  Rig rig_;
  OdometryOptions options_;
  KeyframePolicy keyframePolicy_;
  SlidingWindow window_;
  bool tracking_ = false;
  int nextFrame_ = 0;
  int segment_ = -1;
  int framesSinceKeyframe_ = 0;
  // Buffered while initialising: the frames and their indices.
  std::vector<FrameObservations> pending_;
  std::vector<int> pendingIndices_;
  Eigen::Isometry3d lastWorldFromCamera_ = Eigen::Isometry3d::Identity();
  bool hasLastPose_ = false;
  std::vector<int> rejectedTracks_;
};

}  // namespace lrsvo
