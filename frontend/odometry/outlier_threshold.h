#pragma once

#include <vector>

namespace lrsvo {

// How a window adjustment tells outlying observations from noise.
struct OutlierTestOptions {
  // An observation is an outlier when its reprojection error exceeds
  // `sigmas` times the noise estimated from the errors it is judged among (a
  // Gaussian inlier's 2-D error passes 4 sigma with probability e^-8, 3e-4),
  // kept within [minThreshold_px, maxThreshold_px]. sigmas = 0: always maxThreshold_px.
  double sigmas = 4.0;
  double minThreshold_px = 0.5;  // the noise estimate of a near-perfect window cannot reject its sub-pixel errors
  double maxThreshold_px = 4.0;
  // The share of the window's tracks past the threshold after a solve that
  // stopped short of convergence (at its iteration limit) that says the
  // solve, not the tracks, is wrong: then maxThreshold_px alone applies
  // (findWindowOutliers).
  double maxRejectedTrackFraction = 0.2;
  // An image with at least this many errors may be judged off as a whole
  // and estimate its own noise (findWindowOutliers): the median of n
  // Rayleigh lengths has a relative std of about 0.72 / sqrt(n), 13 % at 30.
  int minImageErrors = 30;
};

// The noise per image axis of 2-D reprojection errors of length error_px,
// estimated robustly: for errors N(0, sigma^2 I) the median length is
// sigma sqrt(2 ln 2) (Rayleigh), and a minority of outliers moves the median
// little. 0 when there are no errors.
double robustNoiseSigma_px(std::vector<double> errors_px);

// The reprojection error above which an observation is an outlier, for the
// errors of the observations that estimate the noise. Throws lrsvo::Error
// on invalid options (validate() below).
double outlierThreshold_px(const std::vector<double>& errors_px, const OutlierTestOptions& options);

// Throws lrsvo::Error unless sigmas >= 0, 0 < minThreshold_px <= maxThreshold_px,
// maxRejectedTrackFraction in [0, 1], all finite, and minImageErrors >= 1.
void validate(const OutlierTestOptions& options);

}  // namespace lrsvo
