#pragma once

#include <vector>

namespace lrsvo {

// What a camera link does to a stream of frames, by the flight's frame index
// (before any is dropped): the conditions a sequence on disk or a live camera
// brings, for the odometry to survive.
struct FrameFaults {
  // From `frame` on, every camera's image is scaled by `gain` (relative to
  // the renderer's own exposure), until the next jump: an auto-exposure step
  // (0.7-1.3 is +-30 % between two frames).
  struct ExposureJump {
    int frame = 0;
    double gain = 1.0;
  };
  std::vector<ExposureJump> exposureJumps;
  std::vector<int> blankFrames;    // every image a uniform mid-grey (a frame lost and sent blank)
  std::vector<int> corruptFrames;  // no image, the source's defect set (a file that does not decode)
  std::vector<int> droppedFrames;  // never delivered: a gap in the stream's times

  bool blank(int frame) const;
  bool corrupt(int frame) const;
  bool dropped(int frame) const;
  // The gain at a frame: the last jump's at or before it, 1 before any.
  double gainAt(int frame) const;
  // Throws lrsvo::Error on a negative frame, a gain that is not positive and
  // finite, or jumps out of frame order.
  void validate() const;
};

}  // namespace lrsvo
