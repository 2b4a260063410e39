#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace lrsvo {

// Settings of pyramidal Lucas-Kanade (cv::calcOpticalFlowPyrLK).
struct KltOptions {
  int window_px = 21;               // side of the square window
  int levels = 3;                   // pyramid levels above the full image
  int iterations = 30;              // per level, at most
  double epsilon_px = 0.01;         // or until a step moves less than this
  double forwardBackward_px = 0.5;  // a point tracked back must land this close to where it started
};

// An image with its pyramid, built once and shared by every KLT call on it
// (tracking in time, forward and backward, and stereo matching). The pyramid
// holds each level's derivatives too: without them every KLT call would
// recompute them over the whole image.
struct KltImage {
  cv::Mat image;                 // CV_8UC1, full resolution
  std::vector<cv::Mat> pyramid;  // from cv::buildOpticalFlowPyramid: level 0, its derivatives, level 1, ...
  int levels() const { return static_cast<int>(pyramid.size() / 2); }  // the full image counts as one
  cv::Mat level(int l) const { return pyramid.at(2 * static_cast<std::size_t>(l)); }
};

// Throws lrsvo::Error unless the image is a non-empty 8-bit grey image.
KltImage makeKltImage(const cv::Mat& image, const KltOptions& options);

// Tracks `points` of `from` into `to`. `positions` holds the starting guesses
// on entry (one per point) and the tracked positions on exit. A point counts
// as found when KLT converges both ways with its window inside the image, and tracking it back
// from its new position lands within forwardBackward_px of where it started.
std::vector<bool> trackKlt(const KltImage& from, const KltImage& to, const std::vector<cv::Point2f>& points,
                           std::vector<cv::Point2f>& positions, const KltOptions& options);

// How far the whole image moved from `from` to `to` (a point at p in `from`
// is near p + shift in `to`), in full-resolution pixels: phase correlation of
// the pyramids' coarsest levels, which finds shifts up to half an image. An
// abrupt attitude change (a gust rolling the aircraft) moves a nadir image
// almost uniformly by hundreds of pixels, beyond what KLT's pyramid reaches
// from a prediction by the tracks' last motion. `response` is the
// correlation peak's height in [0, 1] (low: no clear single shift).
struct ImageShift {
  cv::Point2f shift;
  double response = 0.0;
};
ImageShift globalShift(const KltImage& from, const KltImage& to);

// `image` with a gain and offset that give it the mean and standard deviation
// of `reference`'s intensities (two cameras of a rig expose differently).
cv::Mat withBrightnessOf(const cv::Mat& image, const cv::Mat& reference);

}  // namespace lrsvo
