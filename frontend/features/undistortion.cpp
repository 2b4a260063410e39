#include "lrsvo/frontend/features/undistortion.h"

#include <opencv2/calib3d.hpp>

namespace lrsvo {

namespace {

// The 50 iterations to 1e-6 px of either model's inverse: the default 5 (10
// for the fisheye) leave ~0.1 px at the corners of a strongly distorted lens
// (EuRoC, k1 = -0.28).
const cv::TermCriteria kUndistortionCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-6);

}  // namespace

Undistorter::Undistorter(const PinholeIntrinsics& intrinsics, const LensDistortion& distortion)
    : cameraMatrix_(intrinsics.fx, 0.0, intrinsics.cx, 0.0, intrinsics.fy, intrinsics.cy, 0.0, 0.0, 1.0),
      equidistant_(distortion.model == LensDistortion::Model::kEquidistant),
      identity_(distortion.none()) {
  const auto& c = distortion.coefficients;
  coefficients_ = cv::Mat(std::vector<double>(c.begin(), c.begin() + (equidistant_ ? 4 : 5)), true);
}

std::vector<Eigen::Vector2d> Undistorter::undistort(const std::vector<cv::Point2f>& raw) const {
  std::vector<Eigen::Vector2d> result;
  result.reserve(raw.size());
  if (identity_ || raw.empty()) {
    for (const cv::Point2f& p : raw) result.emplace_back(p.x, p.y);
    return result;
  }
  std::vector<cv::Point2d> in(raw.begin(), raw.end()), out;
  if (equidistant_)
    cv::fisheye::undistortPoints(in, out, cameraMatrix_, coefficients_, cv::noArray(), cameraMatrix_,
                                 kUndistortionCriteria);
  else
    cv::undistortPoints(in, out, cameraMatrix_, coefficients_, cv::noArray(), cameraMatrix_, kUndistortionCriteria);
  for (const cv::Point2d& p : out) result.emplace_back(p.x, p.y);
  return result;
}

std::vector<cv::Point2f> Undistorter::distort(const std::vector<Eigen::Vector2d>& undistorted) const {
  std::vector<cv::Point2f> result;
  result.reserve(undistorted.size());
  if (identity_ || undistorted.empty()) {
    for (const Eigen::Vector2d& p : undistorted)
      result.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    return result;
  }
  std::vector<cv::Point3d> rays;
  rays.reserve(undistorted.size());
  for (const Eigen::Vector2d& p : undistorted)
    rays.emplace_back((p.x() - cameraMatrix_(0, 2)) / cameraMatrix_(0, 0),
                      (p.y() - cameraMatrix_(1, 2)) / cameraMatrix_(1, 1), 1.0);
  std::vector<cv::Point2d> projected;
  if (equidistant_)
    cv::fisheye::projectPoints(rays, projected, cv::Vec3d::zeros(), cv::Vec3d::zeros(), cameraMatrix_, coefficients_);
  else
    cv::projectPoints(rays, cv::Vec3d::zeros(), cv::Vec3d::zeros(), cameraMatrix_, coefficients_, projected);
  for (const cv::Point2d& p : projected) result.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  return result;
}

}  // namespace lrsvo
