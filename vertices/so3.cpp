#include "lrsvo/vertices/so3.h"

#include <cmath>

#include <Eigen/Geometry>

namespace lrsvo {

RodriguesCoefficients rodriguesCoefficientsAt(double theta2) {
  if (theta2 < 1e-6) {
    return {1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0, 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0,
            -1.0 / 6.0 + theta2 / 60.0, -1.0 / 24.0 + theta2 / 360.0};
  }
  const double theta = std::sqrt(theta2);
  const double inverseTheta2 = 1.0 / theta2;  // the one division
  const double halfSine = std::sin(0.5 * theta), halfCosine = std::cos(0.5 * theta);
  const double a = 2.0 * halfSine * halfCosine * theta * inverseTheta2;
  const double b = 2.0 * halfSine * halfSine * inverseTheta2;  // 1 - cos as 2 sin^2(theta / 2): no cancellation
  const double cosine = 1.0 - 2.0 * halfSine * halfSine;
  return {a, b, 0.5 * (cosine - a) * inverseTheta2, 0.5 * (a - 2.0 * b) * inverseTheta2};
}

QuaternionCoefficients quaternionCoefficientsAt(double theta2) {
  if (theta2 < 1e-6) {
    return {1.0 - theta2 / 8.0 + theta2 * theta2 / 384.0, 0.5 - theta2 / 48.0 + theta2 * theta2 / 3840.0,
            -1.0 / 8.0 + theta2 / 192.0, -1.0 / 48.0 + theta2 / 1920.0};
  }
  const double theta = std::sqrt(theta2);
  const double inverseTheta2 = 1.0 / theta2;
  const double w = std::cos(0.5 * theta), k = std::sin(0.5 * theta) * theta * inverseTheta2;
  return {w, k, -0.25 * k, 0.5 * (0.5 * w - k) * inverseTheta2};
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Matrix3d expSO3(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle < 1e-12) return Eigen::Matrix3d::Identity() + skew(omega);
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

Eigen::Matrix3d leftJacobianSO3(const Eigen::Vector3d& omega) {
  const double theta2 = omega.squaredNorm();
  const Eigen::Matrix3d W = skew(omega);
  if (theta2 < 1e-10) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 6.0;
  const double theta = std::sqrt(theta2);
  return Eigen::Matrix3d::Identity() + (1.0 - std::cos(theta)) / theta2 * W +
         (theta - std::sin(theta)) / (theta2 * theta) * W * W;
}

}  // namespace lrsvo
