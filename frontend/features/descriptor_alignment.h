#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace lrsvo {

// Settings of the alignment of two images by oriented ORB matches.
struct DescriptorAlignmentOptions {
  int features = 1500;              // ORB keypoints per image (8 levels, scale factor 1.2)
  int fastThreshold = 12;           // low: a dull or hazy image still gives corners
  double ratio = 0.8;               // best Hamming distance below this times the second best
  double ransacThreshold_px = 4.0;  // homography inliers
  int minInliers = 25;              // fewer: no alignment
};

// One image's ORB keypoints with their descriptors (oriented: a match survives
// any rotation of the image), computed once and matched against many images.
struct DescribedImage {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
};
DescribedImage describeImage(const cv::Mat& image, const DescriptorAlignmentOptions& options);

// The homography that takes pixels of `from` to pixels of `to`, from ORB
// matches (ratio test) in RANSAC. A homography is the exact image motion of a
// pure rotation and, to within relief over range, of a distant near-planar
// scene: a camera 30-150 m above gentle terrain after a gust or a yaw step,
// or after a gap in the stream. OpenCV's RANSAC draws from a fixed seed, so
// the result is the same on every run.
struct ImageAlignment {
  bool found = false;  // at least minInliers inliers
  cv::Matx33d homography = cv::Matx33d::eye();
  int matches = 0;  // passing the ratio test
  int inliers = 0;
};
ImageAlignment alignByDescriptors(const DescribedImage& from, const DescribedImage& to,
                                  const DescriptorAlignmentOptions& options);

// `pixels` moved by a homography.
std::vector<cv::Point2f> transformedPixels(const cv::Matx33d& homography, const std::vector<cv::Point2f>& pixels);

}  // namespace lrsvo
