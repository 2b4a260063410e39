#include "lrsvo/frontend/features/epipolar.h"

#include <cmath>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

Eigen::Matrix3d calibrationMatrix(const PinholeIntrinsics& k) {
  Eigen::Matrix3d m;
  m << k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0;
  return m;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

Eigen::Matrix3d fundamentalMatrix(const PinholeIntrinsics& base, const PinholeIntrinsics& secondary,
                                  const Eigen::Isometry3d& secondaryFromBase) {
  // E = [t]x R for X_c1 = R X_c0 + t; F = K1^-T E K0^-1.
  const Eigen::Matrix3d essential = skew(secondaryFromBase.translation()) * secondaryFromBase.linear();
  return calibrationMatrix(secondary).inverse().transpose() * essential * calibrationMatrix(base).inverse();
}

Eigen::Vector3d epipolarLine(const Eigen::Matrix3d& fundamental, const Eigen::Vector2d& basePixel) {
  const Eigen::Vector3d line = fundamental * basePixel.homogeneous();
  const double norm = line.head<2>().norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw Error("epipolarLine: the base pixel has no epipolar line (it is the epipole, or F is zero)");
  return line / norm;
}

double epipolarDistance(const Eigen::Matrix3d& fundamental, const Eigen::Vector2d& basePixel,
                        const Eigen::Vector2d& secondaryPixel) {
  return std::abs(epipolarLine(fundamental, basePixel).dot(secondaryPixel.homogeneous()));
}

}  // namespace lrsvo
