#pragma once

#include <filesystem>
#include <fstream>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/features/image_front_end.h"
#include "lrsvo/frontend/odometry/frame_estimate.h"

namespace lrsvo {

// Streams a run's outputs into a folder as frames are estimated:
//  trajectory.tum  tracked frames, `t tx ty tz qx qy qz qw` (world-from-camera of the base camera), and
//                  the frames predicted through a short tracking loss, each line ending `# predicted`;
//  extrinsics.csv  per tracked frame and secondary camera, the estimated S and, when known, the true one;
//  frames.csv      per frame: tracked, keyframe, segment, feature counts, window error, time per stage (ms),
//                  realigned, revived, status (frameStatusName) and note (why it has no pose);
//  rig.json        the calibration and the tolerances (the box the bounded S lives in).
// Frames are numbered as the source numbers them: the run's frame i is the
// source's frame firstFrame + i (a run may start part-way, RunOptions::firstFrame).
// Throws lrsvo::Error when the folder cannot be written.
class RunWriter {
 public:
  RunWriter(const std::filesystem::path& outDir, const Rig& rig, GroundTruth truth, int firstFrame = 0);
  void write(const FrameEstimate& estimate, const FrontEndTimings& frontEnd);

 private:
  Rig rig_;
  GroundTruth truth_;
  int firstFrame_ = 0;
  std::ofstream trajectory_, extrinsics_, frames_;
};

}  // namespace lrsvo
