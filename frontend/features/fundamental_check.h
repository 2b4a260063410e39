#pragma once

#include <random>
#include <vector>

#include <Eigen/Core>

namespace lrsvo {

// Which of the point pairs agree with one fundamental matrix, fitted by
// RANSAC (cv::findFundamentalMat) to within threshold_px of the epipolar
// lines: gross outliers of frame-to-frame tracking fail. The draws come from
// `rng` (OpenCV's RANSAC has its own fixed seed, so the pairs are shuffled).
// With fewer than 8 pairs, or no fit, every pair counts as an inlier.
std::vector<bool> fundamentalInliers(const std::vector<Eigen::Vector2d>& before,
                                     const std::vector<Eigen::Vector2d>& after, double threshold_px,
                                     std::mt19937_64& rng);

}  // namespace lrsvo
