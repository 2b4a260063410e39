#include "lrsvo/frontend/features/klt.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// Whether the whole window around p lies in the image: KLT pads the image's
// border, and a window reaching into the padding tracks less precisely.
bool windowInside(const cv::Point2f& p, const cv::Mat& image, int window) {
  const float half = 0.5f * static_cast<float>(window);
  return p.x >= half && p.y >= half && p.x <= image.cols - 1.0f - half && p.y <= image.rows - 1.0f - half;
}

}  // namespace

KltImage makeKltImage(const cv::Mat& image, const KltOptions& options) {
  if (image.empty() || image.type() != CV_8UC1) throw Error("KLT: expected a non-empty 8-bit grey image (CV_8UC1)");
  KltImage result;
  result.image = image;
  cv::buildOpticalFlowPyramid(image, result.pyramid, cv::Size(options.window_px, options.window_px), options.levels,
                              /*withDerivatives=*/true);
  return result;
}

std::vector<bool> trackKlt(const KltImage& from, const KltImage& to, const std::vector<cv::Point2f>& points,
                           std::vector<cv::Point2f>& positions, const KltOptions& options) {
  if (positions.size() != points.size()) throw Error("KLT: one starting guess per point expected");
  std::vector<bool> found(points.size(), false);
  if (points.empty()) return found;
  const cv::Size window(options.window_px, options.window_px);
  const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, options.iterations, options.epsilon_px);
  const int levels = std::min({options.levels, from.levels() - 1, to.levels() - 1});
  std::vector<unsigned char> forward, backward;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(from.pyramid, to.pyramid, points, positions, forward, error, window, levels, stop,
                           cv::OPTFLOW_USE_INITIAL_FLOW);
  std::vector<cv::Point2f> back = points;
  cv::calcOpticalFlowPyrLK(to.pyramid, from.pyramid, positions, back, backward, error, window, levels, stop,
                           cv::OPTFLOW_USE_INITIAL_FLOW);
  const double limit2 = options.forwardBackward_px * options.forwardBackward_px;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const cv::Point2f d = back[i] - points[i];
    found[i] =
        forward[i] && backward[i] && windowInside(positions[i], to.image, options.window_px) && d.dot(d) <= limit2;
  }
  return found;
}

ImageShift globalShift(const KltImage& from, const KltImage& to) {
  const int level = std::min(from.levels(), to.levels()) - 1;
  cv::Mat a, b;
  from.level(level).convertTo(a, CV_32F);
  to.level(level).convertTo(b, CV_32F);
  if (a.size() != b.size()) throw Error("KLT: global shift between images of different sizes");
  cv::Mat window;
  cv::createHanningWindow(window, a.size(), CV_32F);
  ImageShift result;
  const cv::Point2d shift = cv::phaseCorrelate(a, b, window, &result.response);
  const double scale = static_cast<double>(from.image.cols) / a.cols;
  result.shift = cv::Point2f(static_cast<float>(shift.x * scale), static_cast<float>(shift.y * scale));
  return result;
}

cv::Mat withBrightnessOf(const cv::Mat& image, const cv::Mat& reference) {
  cv::Scalar mean, spread, referenceMean, referenceSpread;
  cv::meanStdDev(image, mean, spread);
  cv::meanStdDev(reference, referenceMean, referenceSpread);
  if (!(spread[0] > 0.0)) return image;
  const double gain = referenceSpread[0] / spread[0];
  cv::Mat result;
  image.convertTo(result, CV_8U, gain, referenceMean[0] - gain * mean[0]);
  return result;
}

}  // namespace lrsvo
