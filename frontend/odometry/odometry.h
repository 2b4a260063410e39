#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/frame_estimate.h"
#include "lrsvo/frontend/odometry/keyframe_policy.h"
#include "lrsvo/frontend/odometry/motion_model.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/odometry_options.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/frontend/odometry/sliding_window.h"
#include "lrsvo/frontend/odometry/stereo_start.h"

namespace lrsvo {

// The long-range stereo odometry loop (the paper's Fig. 8) over a stream of
// feature observations (from the image front end or the feature simulator):
//  - starting: the first frame of an attempt is triangulated across the rig;
//    where stereo sees depth (StereoStartOptions: close range, low flight)
//    its stereo structure starts the map at once, with no wait for motion;
//  - initialising: otherwise frames are buffered until the long-range initialiser has
//    its N frames (one each initializationInterval_s); on success every buffered
//    frame gets a pose and the initialised frames fill the window; when only its
//    scale is too uncertain it waits for one more sample and tries again with
//    all of them (up to maxInitializationFrames); on any other failure the
//    oldest buffered frames are given up (untracked) and it tries again;
//  - tracking: each frame's pose by P3P in MLESAC from base observations of
//    mapped points; a keyframe (KeyframePolicy) joins the sliding window, new
//    tracks seen in >= 3 keyframes are triangulated, the window is adjusted
//    (poses, points, shared S: bounded, free or rigid) and the oldest
//    keyframe retired;
//  - too few pose inliers: tracking is lost. Each following frame within
//    relocaliseWithin_s is first posed against the lost segment's map (the
//    front end finds the old tracks again by descriptor alignment); a pose
//    takes the segment up again (FrameEstimate::relocalised). Meanwhile a
//    fresh initialisation starts, and its segment is placed where the last
//    one's constant velocity (motion_model.h) puts its first frame; frames
//    without a pose within maxPrediction_s of the last measured one get that
//    prediction, marked FrameEstimate::predicted.
// The world is the first initialised base camera's frame, in metres.
class Odometry {
 public:
  // Throws lrsvo::Error on an invalid rig or options.
  Odometry(Rig rig, OdometryOptions options);
  // Its window refers to its rig and options: neither copyable nor movable.
  Odometry(const Odometry&) = delete;
  Odometry& operator=(const Odometry&) = delete;

  // Feeds the next frame; returns the estimates that became known, in frame
  // order: none while initialising, all buffered frames when it succeeds,
  // otherwise this frame's. With `secondary`, `frame` may hold base
  // observations alone: the secondary ones are fetched, at most once, only for
  // a frame that is kept (a keyframe, or a frame the initialiser samples); the
  // estimates are the same as for the whole frame.
  std::vector<FrameEstimate> process(const FrameObservations& frame, const SecondaryObservations& secondary = {});
  // Passes over a frame that has nothing to measure (unusable images): it
  // takes the next frame index, which is returned, and gets no estimate here;
  // tracking goes on with the next frame as if this one had not been.
  int skipFrame() { return nextFrame_++; }
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
  std::vector<FrameEstimate> estimate(const FrameObservations& frame, const SecondaryObservations& secondary);
  // Feeds the measured poses to the motion model and predicts the frames
  // lost a short while since, in frame order.
  std::vector<FrameEstimate> settled(std::vector<FrameEstimate> estimates);
  // Where a new segment's first camera (at time t) goes: the motion so far carried on (identity at the start).
  Eigen::Isometry3d segmentPlacement(double time_s) const;
  std::vector<FrameEstimate> initialize();
  // Whether a start that failed only on its scale's std may reach the limit
  // with more samples: the std falls about as 1 / sqrt(samples), and at most
  // maxInitializationFrames are taken.
  bool moreSamplesCouldSettleTheScale(const InitializationResult& result) const;
  // The frames buffered for an initialisation, without a pose, in frame order;
  // the buffer is emptied.
  std::vector<FrameEstimate> givePendingUp();
  // A lost frame's pose against the lost segment's map: whether to try it.
  bool canRelocalise(double time_s) const;
  // The segment taken up again at `estimate`: the frames buffered since the
  // loss are given up (settled() predicts them), then `estimate`.
  std::vector<FrameEstimate> relocalised(FrameEstimate estimate);
  // Starts a segment from one frame's stereo structure (StereoStart::usable).
  FrameEstimate startFromStereo(const FrameObservations& frame, int index, const StereoStart& start);
  FrameEstimate track(const FrameObservations& frame, int index, const SecondaryObservations& secondary);
  // Pose of a frame from its base observations of mapped points (nullopt-like: success flag).
  bool estimateFramePose(const FrameObservations& frame, int index, Eigen::Isometry3d& cameraFromWorld,
                         FrameEstimate& estimate);
  FrameEstimate untracked(const FrameObservations& frame, int index) const;
  // A frame buffered while initialising: the frame, its index, and why the map could not pose it (empty: not tried).
  struct PendingFrame {
    FrameObservations observations;
    int index = 0;
    std::string note;
  };
  // A buffered frame without a pose, with its note.
  FrameEstimate untracked(const PendingFrame& pending) const;
  void clearPending();
  // "N pose inliers of M mapped matches (K needed)", for a frame the map could not pose.
  std::string poseShortfall(const FrameEstimate& estimate) const;
  // Two notes of one frame, either possibly empty, in one.
  static std::string joinedNotes(const std::string& first, const std::string& second);

  Rig rig_;
  OdometryOptions options_;
  KeyframePolicy keyframePolicy_;
  SlidingWindow window_;
  bool tracking_ = false;
  int nextFrame_ = 0;
  int segment_ = -1;
  std::vector<PendingFrame> pending_;    // buffered while initialising, in frame order
  std::vector<std::size_t> samples_;     // the initialiser's samples: positions in pending_
  int samplesWanted_ = 0;                // the next attempt's sample count (initializer.frames, or more)
  double initializeMsUnreported_ = 0.0;  // attempts not yet reported in a frame's times
  ConstantVelocity motion_;              // of the measured poses
  std::vector<int> rejectedTracks_;
};

}  // namespace lrsvo
