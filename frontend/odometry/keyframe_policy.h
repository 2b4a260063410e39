#pragma once

#include "lrsvo/frontend/odometry/observations.h"

namespace lrsvo {

struct KeyframePolicyOptions {
  // A frame becomes a keyframe once the base-camera features it shares with
  // the last keyframe have moved by this much (median, pixels): enough
  // parallax for new structure, few enough to keep tracks in many keyframes.
  double minMedianMotion_px = 30.0;
  // ... or once fewer than this fraction of the last keyframe's tracks remain.
  double minSharedFraction = 0.7;
  // ... or once this long has passed since the last keyframe (10 frames at
  // 30 Hz): a time, not a frame count, so that the window spans the same
  // stretch of flight at any frame rate.
  double maxInterval_s = 1.0 / 3.0;
  // ... but never sooner than this after the last keyframe. Each keyframe
  // costs a window adjustment (about 25 ms on 2 cores when the window is
  // full of close-range tracks), so a keyframe at every frame of a 30 Hz
  // camera at 30 m would not keep up with the camera; 1/15 s leaves a 15 Hz
  // camera free to make every frame a keyframe. 0: no limit.
  double minInterval_s = 1.0 / 15.0;
};

// Decides whether a frame joins the sliding window, from its base-camera
// observations against those of the last keyframe.
class KeyframePolicy {
 public:
  explicit KeyframePolicy(KeyframePolicyOptions options = {}) : options_(options) {}
  const KeyframePolicyOptions& options() const { return options_; }

  bool isKeyframe(const FrameObservations& lastKeyframe, const FrameObservations& frame) const;

 private:
  KeyframePolicyOptions options_;
};

}  // namespace lrsvo
