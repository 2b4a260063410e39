#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

// Images a source produces only when asked: a renderer's secondary cameras,
// which the odometry needs only on the frames it keeps. Each is made on first
// request and kept. Not thread-safe.
class DeferredImages {
 public:
  using Produce = std::function<cv::Mat(int camera)>;
  explicit DeferredImages(Produce produce) : produce_(std::move(produce)) {}
  const cv::Mat& image(int camera);
  bool made(int camera) const { return made_.contains(camera); }

 private:
  Produce produce_;
  std::map<int, cv::Mat> made_;
};

// One time step of a camera rig: an 8-bit grey image per camera, as captured
// (distorted by that camera's lens model, see FrameSource::distortion).
struct StereoFrame {
  int index = 0;  // 0, 1, 2, ... in the order the source delivers them
  double time_s = 0.0;
  std::vector<cv::Mat> images;  // [camera], CV_8UC1; empty for a camera the source defers
  // Set by a source that defers some cameras' images (shared by copies of the
  // frame; it may call back into the source, so use it while the source lives).
  std::shared_ptr<DeferredImages> deferred;
  // Set by a source that could not produce this frame's images (a missing or
  // undecodable file); the frame is still delivered, so that a run can go on
  // without it (frameDefect, frame_check.h).
  std::string defect;

  int cameraCount() const { return static_cast<int>(images.size()); }
  // Camera k's image: images[k], or the deferred one, made now if not yet.
  // Throws lrsvo::Error for k outside [0, cameraCount()).
  const cv::Mat& image(int camera) const;
};

// A camera's lens distortion; all zero for an ideal pinhole (synthetic images,
// rectified data sets).
struct LensDistortion {
  // OpenCV's radial-tangential model, coefficients [k1 k2 p1 p2 k3] (EuRoC's
  // "radial-tangential", Kalibr's "radtan"); or the equidistant fisheye model
  // of cv::fisheye, [k1 k2 k3 k4] in the first four (EuRoC's and Kalibr's
  // "equidistant").
  enum class Model { kRadialTangential, kEquidistant };
  Model model = Model::kRadialTangential;
  std::array<double, 5> coefficients{};
  bool none() const {
    for (double c : coefficients)
      if (c != 0.0) return false;
    return true;
  }
};

// A pose of the base camera at a time: world-from-camera (TUM's convention).
struct TimedPose {
  double time_s = 0.0;
  Eigen::Isometry3d worldFromCamera = Eigen::Isometry3d::Identity();
};

// What a source knows of the truth; either part may be empty.
struct GroundTruth {
  std::vector<TimedPose> poses;                                         // base camera, by time
  std::vector<std::vector<VertexStereoExtrinsic::Vector6>> extrinsics;  // [frame][k - 1]: camera k's true s
};

// A sequence of rig images: a data set on disk (EuRoC, KITTI layout) or a
// synthetic flight rendered on the fly. The odometry reads frames one by one.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual std::string name() const = 0;
  // The calibration: pinhole intrinsics of the undistorted images, the
  // secondary cameras' extrinsics and their tolerances.
  virtual const Rig& rig() const = 0;
  // Per camera, the lens distortion of the captured images.
  virtual const std::vector<LensDistortion>& distortion() const = 0;
  // Frames the source will deliver, or -1 when not known in advance.
  virtual int frameCount() const = 0;
  // The next frame, or std::nullopt after the last.
  virtual std::optional<StereoFrame> next() = 0;
  // Passes over the next `count` frames (fewer at the end) without delivering
  // them; a source that can seek does it without reading or rendering them.
  virtual void skip(int count) {
    for (int i = 0; i < count && next(); ++i) {
    }
  }
  virtual GroundTruth groundTruth() const { return {}; }
};

}  // namespace lrsvo
