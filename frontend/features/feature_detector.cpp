#include "lrsvo/frontend/features/feature_detector.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

// Detection keeps many candidates; bucketing then thins them out.
constexpr int kCandidateCap = 5000;

using DetectorFactory = std::function<cv::Ptr<cv::Feature2D>(const DetectorOptions&)>;

const std::map<std::string, DetectorFactory>& registry() {
  static const std::map<std::string, DetectorFactory> factories = {
      {"gftt",
       [](const DetectorOptions& o) { return cv::GFTTDetector::create(kCandidateCap, o.gfttQuality, 0.0, 3, false); }},
      {"fast", [](const DetectorOptions& o) { return cv::FastFeatureDetector::create(o.fastThreshold, true); }},
      {"orb",
       [](const DetectorOptions& o) {
         return cv::ORB::create(kCandidateCap, 1.2f, o.orbLevels, o.orbPatch_px, 0, 2, cv::ORB::FAST_SCORE,
                                o.orbPatch_px, o.fastThreshold);
       }},
  };
  return factories;
}

// The grid cell of a pixel.
std::size_t cellOf(const cv::Point2f& p, const cv::Size& size, const DetectorOptions& options) {
  const int x = std::clamp(static_cast<int>(p.x), 0, size.width - 1);
  const int y = std::clamp(static_cast<int>(p.y), 0, size.height - 1);
  return static_cast<std::size_t>((y * options.gridRows / size.height) * options.gridColumns +
                                  x * options.gridColumns / size.width);
}

// Up to `wanted` keypoints, strongest first, none where `free` is 0 (each kept
// keypoint clears a disc of minDistance in `free`). A first pass fills each
// cell up to `perCell` counting what it holds already (`counts`); a second
// fills what textureless cells left over.
std::vector<cv::KeyPoint> bucket(std::vector<cv::KeyPoint> keypoints, cv::Mat& free, const DetectorOptions& options,
                                 std::vector<int> counts, int perCell, int wanted) {
  std::stable_sort(keypoints.begin(), keypoints.end(),
                   [](const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; });
  std::vector<cv::KeyPoint> kept;
  for (int pass = 0; pass < 2; ++pass) {
    for (const cv::KeyPoint& k : keypoints) {
      if (static_cast<int>(kept.size()) >= wanted) return kept;
      int& count = counts[cellOf(k.pt, free.size(), options)];
      const int x = std::clamp(cvRound(k.pt.x), 0, free.cols - 1), y = std::clamp(cvRound(k.pt.y), 0, free.rows - 1);
      if ((pass == 0 && count >= perCell) || free.at<unsigned char>(y, x) == 0) continue;
      kept.push_back(k);
      ++count;
      cv::circle(free, k.pt, static_cast<int>(std::ceil(options.minDistance_px)), cv::Scalar(0), cv::FILLED);
    }
  }
  return kept;
}

}  // namespace

FeatureDetector::FeatureDetector(const DetectorOptions& options) : options_(options) {
  const auto found = registry().find(options.name);
  if (found == registry().end()) {
    std::string names;
    for (const std::string& n : featureDetectorNames()) names += " " + n;
    throw Error("feature detector: unknown name '" + options.name + "', expected one of:" + names);
  }
  if (options.gridColumns < 1 || options.gridRows < 1 || !(options.minDistance_px >= 0.0) || options.border_px < 0)
    throw Error("feature detector: the grid needs at least one cell, the minimum distance and border must be >= 0");
  detector_ = found->second(options);
}

DetectedFeatures FeatureDetector::detect(const cv::Mat& image, const std::vector<cv::Point2f>& existing,
                                         int wanted) const {
  DetectedFeatures result;
  if (wanted <= 0) return result;
  cv::Mat mask(image.size(), CV_8UC1, cv::Scalar(0));
  const int border = options_.border_px;
  if (2 * border >= image.cols || 2 * border >= image.rows) return result;
  mask(cv::Rect(border, border, image.cols - 2 * border, image.rows - 2 * border)).setTo(255);
  const int radius = static_cast<int>(std::ceil(options_.minDistance_px));
  for (const cv::Point2f& p : existing) cv::circle(mask, p, radius, cv::Scalar(0), cv::FILLED);
  const int cells = options_.gridColumns * options_.gridRows;
  const int perCell = (static_cast<int>(existing.size()) + wanted + cells - 1) / cells;
  std::vector<int> counts(static_cast<std::size_t>(cells), 0);
  for (const cv::Point2f& p : existing) ++counts[cellOf(p, image.size(), options_)];
  std::vector<cv::KeyPoint> keypoints;
  if (hasDescriptors()) {
    detector_->detect(image, keypoints, mask);  // ORB needs the whole image for its pyramid and patches
  } else {
    // Only the cells short of their share are searched: topping up costs little.
    for (int row = 0; row < options_.gridRows; ++row)
      for (int column = 0; column < options_.gridColumns; ++column) {
        if (counts[static_cast<std::size_t>(row * options_.gridColumns + column)] >= perCell) continue;
        const cv::Point corner(column * image.cols / options_.gridColumns, row * image.rows / options_.gridRows);
        const cv::Rect cell(corner, cv::Point((column + 1) * image.cols / options_.gridColumns,
                                              (row + 1) * image.rows / options_.gridRows));
        std::vector<cv::KeyPoint> found;
        detector_->detect(image(cell), found, mask(cell));
        for (cv::KeyPoint& k : found) {
          k.pt += cv::Point2f(static_cast<float>(corner.x), static_cast<float>(corner.y));
          keypoints.push_back(k);
        }
      }
  }
  keypoints = bucket(std::move(keypoints), mask, options_, std::move(counts), perCell, wanted);
  if (hasDescriptors()) {
    for (cv::KeyPoint& k : keypoints) k.angle = 0.0f;          // upright
    detector_->compute(image, keypoints, result.descriptors);  // drops keypoints too near the border
  }
  cv::KeyPoint::convert(keypoints, result.points);
  return result;
}

std::vector<std::string> featureDetectorNames() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

}  // namespace lrsvo
