#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

namespace lrsvo {

// How features are found: which detector, and how they are spread over the
// image (a grid of cells, at most a few per cell, none near an existing track).
struct DetectorOptions {
  std::string name = "gftt";  // one of featureDetectorNames()
  int gridColumns = 8;
  int gridRows = 6;
  double minDistance_px = 12.0;  // from existing tracks and from each other
  int border_px = 11;            // none nearer the image's edge (half a KLT window)
  double gfttQuality = 0.01;     // "gftt": corner response relative to the image's best
  int fastThreshold = 20;        // "fast" and "orb": FAST intensity threshold
  int orbLevels = 4;             // "orb": pyramid levels (scale factor 1.2)
  int orbPatch_px = 31;          // "orb": descriptor patch size and border
};

// Features found in one image; descriptors (one row each) only when the
// detector has them (ORB).
struct DetectedFeatures {
  std::vector<cv::Point2f> points;
  cv::Mat descriptors;
};

// A corner detector with bucketing: the image is split into a grid and each
// cell keeps its strongest corners, up to an equal share of `wanted`; the
// strongest of the rest make up for cells without texture.
// Upright: descriptors are computed at orientation 0 (the aircraft barely rolls).
class FeatureDetector {
 public:
  explicit FeatureDetector(const DetectorOptions& options);
  const DetectorOptions& options() const { return options_; }
  bool hasDescriptors() const { return options_.name == "orb"; }
  // Up to `wanted` features at least minDistance_px from every point of `existing`.
  DetectedFeatures detect(const cv::Mat& image, const std::vector<cv::Point2f>& existing, int wanted) const;

 private:
  DetectorOptions options_;
  cv::Ptr<cv::Feature2D> detector_;
};

// The registered detector names: "gftt", "fast", "orb".
std::vector<std::string> featureDetectorNames();

}  // namespace lrsvo
