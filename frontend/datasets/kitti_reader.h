#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "lrsvo/frontend/datasets/frame_source.h"

namespace lrsvo {

// A sequence in the KITTI odometry layout: SEQ/image_0/000000.png (base, left),
// SEQ/image_1/000000.png (right), SEQ/calib.txt with the 3x4 projection rows
// "P0: ..." and "P1: ...", SEQ/times.txt (seconds, one a line). KITTI is
// rectified horizontal stereo without distortion: camera 1 sits at
// x = -P1[0][3] / fx along the base camera's x axis, unrotated. Ground truth,
// when present: SEQ/poses.txt, else the data set's poses/<SEQ name>.txt two
// levels up (sequences/00 -> poses/00.txt): 12 numbers a line, the 3x4
// world-from-camera-0 matrix of each frame. An image that cannot be read, or
// differs in size from the first, is reported in its frame's defect.
class KittiSource : public FrameSource {
 public:
  explicit KittiSource(const std::string& directory);
  std::string name() const override { return "kitti:" + directory_; }
  const Rig& rig() const override { return rig_; }
  const std::vector<LensDistortion>& distortion() const override { return distortion_; }
  int frameCount() const override { return static_cast<int>(times_.size()); }
  std::optional<StereoFrame> next() override;
  void skip(int count) override { next_ = std::min(frameCount(), next_ + std::max(count, 0)); }
  GroundTruth groundTruth() const override { return truth_; }

 private:
  std::string imagePath(int camera, int frame) const;

  std::string directory_;
  Rig rig_;
  std::vector<LensDistortion> distortion_{2};
  std::vector<double> times_;
  int next_ = 0;
  GroundTruth truth_;
};

}  // namespace lrsvo
