#include "lrsvo/frontend/odometry/outlier_threshold.h"

#include <algorithm>
#include <cmath>

#include "lrsvo/graph/error.h"

namespace lrsvo {

double robustNoiseSigma_px(std::vector<double> errors_px) {
  if (errors_px.empty()) return 0.0;
  const auto middle = errors_px.begin() + static_cast<std::ptrdiff_t>(errors_px.size() / 2);
  std::nth_element(errors_px.begin(), middle, errors_px.end());
  return *middle / std::sqrt(2.0 * std::log(2.0));
}

double outlierThreshold_px(const std::vector<double>& errors_px, const OutlierTestOptions& options) {
  validate(options);
  if (options.sigmas == 0.0 || errors_px.empty()) return options.maxThreshold_px;
  return std::clamp(options.sigmas * robustNoiseSigma_px(errors_px), options.minThreshold_px, options.maxThreshold_px);
}

void validate(const OutlierTestOptions& options) {
  if (!(std::isfinite(options.sigmas) && options.sigmas >= 0.0 && std::isfinite(options.maxThreshold_px) &&
        options.minThreshold_px > 0.0 && options.minThreshold_px <= options.maxThreshold_px &&
        options.maxRejectedTrackFraction >= 0.0 && options.maxRejectedTrackFraction <= 1.0 &&
        options.minImageErrors >= 1))
    throw Error(
        "outlier test: sigmas must be >= 0, 0 < minThreshold_px <= maxThreshold_px, maxRejectedTrackFraction in "
        "[0, 1], all finite, and minImageErrors >= 1");
}

}  // namespace lrsvo
