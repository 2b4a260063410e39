#pragma once

#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/frontend/datasets/frame_source.h"
#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

// Writes a stereo sequence in the EuRoC MAV layout, as
// frontend/datasets/euroc_reader.h reads it back:
//   DIR/mav0/body.yaml
//   DIR/mav0/cam<k>/data/<ns>.png, cam<k>/data.csv ("#timestamp [ns],filename"),
//   cam<k>/sensor.yaml (T_BS with body = cam0, rate_hz, resolution,
//     camera_model pinhole, intrinsics [fu, fv, cu, cv],
//     distortion_model radial-tangential, distortion_coefficients [0, 0, 0, 0]),
//   DIR/groundtruth_cam0_tum.txt (t tx ty tz qx qy qz qw: world-from-cam0),
//   DIR/true_extrinsics.csv (per frame and secondary camera k: its true s).
// Timestamps are the frame times in nanoseconds.
class EurocWriter {
 public:
  // Creates the folders and writes the calibration files; throws
  // lrsvo::Error when a file cannot be written.
  EurocWriter(const std::string& directory, const Rig& rig, double rate_hz);

  // One frame: its images, the base camera's true pose and every secondary camera's true extrinsic.
  void write(const StereoFrame& frame, const Eigen::Isometry3d& worldFromBase,
             const std::vector<VertexStereoExtrinsic::Vector6>& trueExtrinsics);

 private:
  std::string directory_;
  int cameras_ = 0;
  std::vector<std::ofstream> dataCsv_;  // [camera]
  std::ofstream groundTruth_, extrinsics_;
};

}  // namespace lrsvo
