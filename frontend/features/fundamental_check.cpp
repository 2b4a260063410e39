#include "lrsvo/frontend/features/fundamental_check.h"

#include <algorithm>
#include <numeric>

#include <opencv2/calib3d.hpp>

#include "lrsvo/graph/error.h"

namespace lrsvo {

std::vector<bool> fundamentalInliers(const std::vector<Eigen::Vector2d>& before,
                                     const std::vector<Eigen::Vector2d>& after, double threshold_px,
                                     std::mt19937_64& rng) {
  if (before.size() != after.size()) throw Error("fundamental check: one 'after' point per 'before' point expected");
  std::vector<bool> inlier(before.size(), true);
  if (before.size() < 8) return inlier;
  std::vector<std::size_t> order(before.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<cv::Point2d> a, b;
  for (std::size_t i : order) {
    a.emplace_back(before[i].x(), before[i].y());
    b.emplace_back(after[i].x(), after[i].y());
  }
  std::vector<unsigned char> mask;
  const cv::Mat f = cv::findFundamentalMat(a, b, cv::FM_RANSAC, threshold_px, 0.999, mask);
  if (f.empty() || mask.size() != order.size()) return inlier;
  for (std::size_t j = 0; j < order.size(); ++j) inlier[order[j]] = mask[j] != 0;
  return inlier;
}

}  // namespace lrsvo
