#include "lrsvo/frontend/features/feature_detector.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <utility>

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

bool stronger(const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; }

// Visits the keypoints of every list strongest first, equal responses in the
// order of the lists and then of their places in a list: the order of one
// stable sort of the lists joined, but merged as it is read, so that bucketing
// reads no further than it needs. visit returns what to read next: kNext, kSkipList
// (nothing more of this keypoint's list) or kStop. Each list must be sorted by
// `stronger` already.
enum class Read { kNext, kSkipList, kStop };
template <typename Visit>
void strongestFirst(const std::vector<std::vector<cv::KeyPoint>>& lists, const Visit& visit) {
  using Head = std::pair<std::size_t, std::size_t>;  // list, place in it
  const auto after = [&](const Head& a, const Head& b) {
    const float ra = lists[a.first][a.second].response, rb = lists[b.first][b.second].response;
    return ra != rb ? ra < rb : a.first > b.first;
  };
  std::priority_queue<Head, std::vector<Head>, decltype(after)> heads(after);
  for (std::size_t list = 0; list < lists.size(); ++list)
    if (!lists[list].empty()) heads.push({list, 0});
  while (!heads.empty()) {
    const auto [list, place] = heads.top();
    heads.pop();
    const Read read = visit(lists[list][place], list);
    if (read == Read::kStop) return;
    if (read == Read::kNext && place + 1 < lists[list].size()) heads.push({list, place + 1});
  }
}

// Up to `wanted` keypoints, strongest first, none where `free` is 0 (each kept
// keypoint clears a disc of minDistance in `free`). A first pass fills each
// cell up to `perCell` counting what it holds already (`counts`); a second
// fills what textureless cells left over.
std::vector<cv::KeyPoint> bucket(std::vector<std::vector<cv::KeyPoint>> lists, cv::Mat& free,
                                 const DetectorOptions& options, std::vector<int> counts, int perCell, int wanted) {
  // The one cell all of a list's keypoints lie in, if any: once that cell is
  // full, the first pass can pass over the rest of the list.
  std::vector<std::size_t> listCell(lists.size(), counts.size());
  for (std::size_t i = 0; i < lists.size(); ++i) {
    std::vector<cv::KeyPoint>& list = lists[i];
    if (!std::is_sorted(list.begin(), list.end(), stronger)) std::stable_sort(list.begin(), list.end(), stronger);
    if (list.empty()) continue;
    const std::size_t cell = cellOf(list.front().pt, free.size(), options);
    if (std::all_of(list.begin(), list.end(),
                    [&](const cv::KeyPoint& k) { return cellOf(k.pt, free.size(), options) == cell; }))
      listCell[i] = cell;
  }
  std::vector<cv::KeyPoint> kept;
  for (int pass = 0; pass < 2 && static_cast<int>(kept.size()) < wanted; ++pass)
    strongestFirst(lists, [&](const cv::KeyPoint& k, std::size_t list) {
      const std::size_t cell = cellOf(k.pt, free.size(), options);
      if (pass == 0 && counts[cell] >= perCell) return listCell[list] == cell ? Read::kSkipList : Read::kNext;
      const int x = std::clamp(cvRound(k.pt.x), 0, free.cols - 1), y = std::clamp(cvRound(k.pt.y), 0, free.rows - 1);
      if (free.at<unsigned char>(y, x) == 0) return Read::kNext;
      kept.push_back(k);
      ++counts[cell];
      cv::circle(free, k.pt, static_cast<int>(std::ceil(options.minDistance_px)), cv::Scalar(0), cv::FILLED);
      return static_cast<int>(kept.size()) < wanted ? Read::kNext : Read::kStop;
    });
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
  std::vector<std::vector<cv::KeyPoint>> candidates;  // one list per cell searched (ORB: one list)
  if (hasDescriptors()) {
    detector_->detect(image, candidates.emplace_back(), mask);  // ORB needs the whole image for its pyramid and patches
  } else {
    // Only the cells short of their share are searched: topping up costs little.
    for (int row = 0; row < options_.gridRows; ++row)
      for (int column = 0; column < options_.gridColumns; ++column) {
        if (counts[static_cast<std::size_t>(row * options_.gridColumns + column)] >= perCell) continue;
        const cv::Point corner(column * image.cols / options_.gridColumns, row * image.rows / options_.gridRows);
        const cv::Rect cell(corner, cv::Point((column + 1) * image.cols / options_.gridColumns,
                                              (row + 1) * image.rows / options_.gridRows));
        std::vector<cv::KeyPoint>& found = candidates.emplace_back();
        detector_->detect(image(cell), found, mask(cell));
        for (cv::KeyPoint& k : found) k.pt += cv::Point2f(static_cast<float>(corner.x), static_cast<float>(corner.y));
      }
  }
  std::vector<cv::KeyPoint> keypoints =
      bucket(std::move(candidates), mask, options_, std::move(counts), perCell, wanted);
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
