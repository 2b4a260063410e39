#include "lrsvo/eval/depth_resolution.h"

#include <limits>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

void requirePositive(double focal_px, double baseline_m, double depth_m) {
  if (!(focal_px > 0.0 && baseline_m > 0.0 && depth_m > 0.0))
    throw Error("depth resolution: focal length, baseline and depth must be positive");
}

}  // namespace

double disparity_px(double focal_px, double baseline_m, double depth_m) {
  requirePositive(focal_px, baseline_m, depth_m);
  return focal_px * baseline_m / depth_m;
}

double depthStepExact_m(double focal_px, double baseline_m, double depth_m) {
  const double d = disparity_px(focal_px, baseline_m, depth_m);
  if (d <= 1.0) return std::numeric_limits<double>::infinity();
  return focal_px * baseline_m / (d - 1.0) - depth_m;
}

double depthStepNearer_m(double focal_px, double baseline_m, double depth_m) {
  const double d = disparity_px(focal_px, baseline_m, depth_m);
  return depth_m - focal_px * baseline_m / (d + 1.0);
}

double depthStepFirstOrder_m(double focal_px, double baseline_m, double depth_m) {
  requirePositive(focal_px, baseline_m, depth_m);
  return depth_m * depth_m / (focal_px * baseline_m);
}

}  // namespace lrsvo
