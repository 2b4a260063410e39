#include "lrsvo/frontend/features/descriptor_alignment.h"

#include <algorithm>

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {

DescribedImage describeImage(const cv::Mat& image, const DescriptorAlignmentOptions& options) {
  if (image.empty() || image.type() != CV_8UC1) throw Error("descriptor alignment: needs an 8-bit grey image");
  const cv::Ptr<cv::ORB> orb =
      cv::ORB::create(options.features, 1.2f, 8, 31, 0, 2, cv::ORB::HARRIS_SCORE, 31, options.fastThreshold);
  DescribedImage described;
  orb->detectAndCompute(image, cv::noArray(), described.keypoints, described.descriptors);
  return described;
}

ImageAlignment alignByDescriptors(const DescribedImage& from, const DescribedImage& to,
                                  const DescriptorAlignmentOptions& options) {
  ImageAlignment alignment;
  if (from.descriptors.rows < 2 || to.descriptors.rows < 2) return alignment;
  std::vector<std::vector<cv::DMatch>> candidates;
  cv::BFMatcher(cv::NORM_HAMMING).knnMatch(from.descriptors, to.descriptors, candidates, 2);
  std::vector<cv::Point2f> source, target;
  for (const std::vector<cv::DMatch>& pair : candidates) {
    if (pair.size() < 2 || !(pair[0].distance < options.ratio * pair[1].distance)) continue;
    source.push_back(from.keypoints[static_cast<std::size_t>(pair[0].queryIdx)].pt);
    target.push_back(to.keypoints[static_cast<std::size_t>(pair[0].trainIdx)].pt);
  }
  alignment.matches = static_cast<int>(source.size());
  if (alignment.matches < std::max(4, options.minInliers)) return alignment;
  std::vector<unsigned char> inlier;
  const cv::Mat homography = cv::findHomography(source, target, cv::RANSAC, options.ransacThreshold_px, inlier);
  if (homography.empty()) return alignment;
  alignment.inliers = cv::countNonZero(inlier);
  alignment.found = alignment.inliers >= options.minInliers;
  alignment.homography = cv::Matx33d(homography);
  return alignment;
}

std::vector<cv::Point2f> transformedPixels(const cv::Matx33d& homography, const std::vector<cv::Point2f>& pixels) {
  std::vector<cv::Point2f> moved;
  if (!pixels.empty()) cv::perspectiveTransform(pixels, moved, cv::Mat(homography));
  return moved;
}

}  // namespace lrsvo
