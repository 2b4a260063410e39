#pragma once

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/frontend/datasets/frame_source.h"

namespace lrsvo {

// Maps pixels between a camera's captured (distorted) image and its ideal
// pinhole image with the same intrinsics. Features are found and tracked on
// the raw images; only their positions are undistorted.
class Undistorter {
 public:
  Undistorter(const PinholeIntrinsics& intrinsics, const LensDistortion& distortion);
  bool identity() const { return identity_; }
  std::vector<Eigen::Vector2d> undistort(const std::vector<cv::Point2f>& raw) const;
  // The inverse: where undistorted pixels appear in the captured image.
  std::vector<cv::Point2f> distort(const std::vector<Eigen::Vector2d>& undistorted) const;

 private:
  cv::Matx33d cameraMatrix_;
  cv::Mat coefficients_;  // five for the radial-tangential model, four for the equidistant one
  bool equidistant_;
  bool identity_;
};

}  // namespace lrsvo
