#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "lrsvo/frontend/datasets/frame_source.h"

namespace lrsvo {

// One camera's calibration as EuRoC's cam<i>/sensor.yaml gives it.
struct EurocCameraCalibration {
  Camera camera;                                                     // intrinsics [fu fv cu cv], resolution
  LensDistortion distortion;                                         // distortion_model and its coefficients
  Eigen::Isometry3d bodyFromSensor = Eigen::Isometry3d::Identity();  // T_BS
};

// Reads cam<i>/sensor.yaml. EuRoC's files are YAML with a "%YAML:1.0" header
// and nested T_BS maps; only the few keys needed are read, by hand, so that a
// file with or without the header reads alike. camera_model must be pinhole
// (or absent); distortion_model radial-tangential (or Kalibr's radtan: 4
// coefficients k1 k2 p1 p2, or 5 with k3; the model of a file without the
// key), equidistant (4: k1 k2 k3 k4, the fisheye model) or none. Throws
// lrsvo::Error naming the file and the missing, malformed or unsupported key.
EurocCameraCalibration readEurocSensor(const std::string& path);

// A stereo sequence in the EuRoC MAV layout: DIR/mav0/cam0/data.csv,
// cam0/data/<ns>.png, cam0/sensor.yaml, and cam1 likewise. Camera 0 is the
// base; cam1's extrinsic comes from the two T_BS. A frame pairs a cam0 and a
// cam1 image whose timestamps differ by at most kStereoSyncTolerance_ns, and
// takes cam0's time. Within the stretch both cameras recorded, an image of
// either camera without such a partner is a frame of its own whose defect
// names the missing camera, so that it is reported like any unusable frame,
// not dropped unseen; one camera's images before the other's first or after
// its last are not frames.
// Ground truth, when present: DIR/groundtruth_cam0_tum.txt (poses of cam0),
// else DIR/groundtruth_body_tum.txt (poses of the body, moved to cam0 by T_BS),
// else EuRoC's own mav0/state_groundtruth_estimate0/data.csv (the body's
// poses likewise).
// An image that cannot be read, or is not the size sensor.yaml gives, is
// reported in its frame's defect; the sequence goes on.
class EurocSource : public FrameSource {
 public:
  // The largest difference of a stereo pair's timestamps: writers that round
  // their clocks to a microsecond or a millisecond still pair, while images
  // taken a frame apart (a few milliseconds even at 200 Hz) do not.
  static constexpr long long kStereoSyncTolerance_ns = 1'000'000;

  explicit EurocSource(const std::string& directory);
  std::string name() const override { return "euroc:" + directory_; }
  const Rig& rig() const override { return rig_; }
  const std::vector<LensDistortion>& distortion() const override { return distortion_; }
  int frameCount() const override { return static_cast<int>(frames_.size()); }
  std::optional<StereoFrame> next() override;
  void skip(int count) override {
    next_ = std::min(frames_.size(), next_ + static_cast<std::size_t>(std::max(count, 0)));
  }
  GroundTruth groundTruth() const override { return truth_; }

 private:
  struct FramePaths {
    double time_s = 0.0;
    std::array<std::string, 2> images;  // empty where that camera has no image at this time
    bool paired() const { return !images[0].empty() && !images[1].empty(); }
  };
  // Both cameras' images (by timestamp, ns; neither list empty) merged in
  // time order over the stretch both recorded: pairs, and the images left
  // without a partner each as a frame of its own.
  static std::vector<FramePaths> pairByTime(const std::map<long long, std::string>& cam0,
                                            const std::map<long long, std::string>& cam1);

  std::string directory_;
  Rig rig_;
  std::vector<LensDistortion> distortion_;
  std::vector<FramePaths> frames_;
  std::size_t next_ = 0;
  GroundTruth truth_;
};

}  // namespace lrsvo
