#include "lrsvo/sim/frame_faults.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

bool listed(const std::vector<int>& frames, int frame) {
  return std::find(frames.begin(), frames.end(), frame) != frames.end();
}

}  // namespace

bool FrameFaults::blank(int frame) const { return listed(blankFrames, frame); }
bool FrameFaults::corrupt(int frame) const { return listed(corruptFrames, frame); }
bool FrameFaults::dropped(int frame) const { return listed(droppedFrames, frame); }

double FrameFaults::gainAt(int frame) const {
  double gain = 1.0;
  for (const ExposureJump& jump : exposureJumps)
    if (jump.frame <= frame) gain = jump.gain;
  return gain;
}

void FrameFaults::validate() const {
  for (std::size_t i = 0; i < exposureJumps.size(); ++i) {
    const ExposureJump& jump = exposureJumps[i];
    if (jump.frame < 0 || !(jump.gain > 0.0 && std::isfinite(jump.gain)))
      throw Error("frame faults: exposure jump " + std::to_string(i) + " needs a frame >= 0 and a gain > 0");
    if (i > 0 && jump.frame <= exposureJumps[i - 1].frame)
      throw Error("frame faults: exposure jumps must be in increasing frame order");
  }
  for (const std::vector<int>* frames : {&blankFrames, &corruptFrames, &droppedFrames})
    for (int frame : *frames)
      if (frame < 0) throw Error("frame faults: a faulty frame index is negative: " + std::to_string(frame));
}

}  // namespace lrsvo
