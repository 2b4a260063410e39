#include "lrsvo/frontend/features/frame_check.h"

#include <cstdio>

#include <opencv2/core.hpp>

namespace lrsvo {
namespace {

std::string imageDefect(const cv::Mat& image, const Camera& camera, const FrameCheckOptions& options) {
  if (std::string defect = imageShapeDefect(image, camera); !defect.empty()) return defect;
  cv::Scalar mean, deviation;
  cv::meanStdDev(image, mean, deviation);
  if (deviation[0] < options.minGreyStd) {
    char text[96];
    std::snprintf(text, sizeof text, "a blank image (grey %.1f +- %.2f)", mean[0], deviation[0]);
    return text;
  }
  return {};
}

}  // namespace

std::string imageShapeDefect(const cv::Mat& image, const Camera& camera) {
  if (image.empty()) return "no image";
  if (image.type() != CV_8UC1) return "not an 8-bit grey image";
  if (image.cols != camera.width || image.rows != camera.height)
    return "the image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) + ", the calibration says " +
           std::to_string(camera.width) + "x" + std::to_string(camera.height);
  return {};
}

std::string frameDefect(const StereoFrame& frame, const Rig& rig, const FrameCheckOptions& options) {
  if (!frame.defect.empty()) return frame.defect;
  if (frame.cameraCount() != static_cast<int>(rig.cameras.size()))
    return std::to_string(frame.cameraCount()) + " images for a rig of " + std::to_string(rig.cameras.size()) +
           " cameras";
  for (int c = 0; c < frame.cameraCount(); ++c) {
    const cv::Mat& image = frame.images[static_cast<std::size_t>(c)];
    if (c > 0 && image.empty() && frame.deferred) continue;
    const std::string defect = imageDefect(image, rig.cameras[static_cast<std::size_t>(c)], options);
    if (!defect.empty()) return "camera " + std::to_string(c) + ": " + defect;
  }
  return {};
}

}  // namespace lrsvo
