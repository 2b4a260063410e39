#pragma once

#include "frontend/observations.h"

namespace lrsvo {

struct KeyframePolicyOptions {
  // A frame becomes a keyframe once the base-camera features it shares with
  // the last keyframe have moved by this much (median, pixels): enough
  // parallax for new structure, few enough to keep tracks in many keyframes.
  double minMedianMotion_px = 30.0;
  // ... or once fewer than this fraction of the last keyframe's tracks remain.
  double minSharedFraction = 0.7;
  // ... or after this many frames at most.
  int maxFrameGap = 10;
};

// Decides whether a frame joins the sliding window, from its base-camera
// observations against those of the last keyframe.
class KeyframePolicy {
 public:
  explicit KeyframePolicy(KeyframePolicyOptions options = {}) : options_(options) {}
  const KeyframePolicyOptions& options() const { return options_; }

  // `framesSinceKeyframe` counts from the last keyframe (1 = the next frame).
  bool isKeyframe(const FrameObservations& lastKeyframe, const FrameObservations& frame, int framesSinceKeyframe) const;

 private:
  KeyframePolicyOptions options_;
};

}  // namespace lrsvo
