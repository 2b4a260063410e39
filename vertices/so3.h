#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lrsvo {

// Skew-symmetric matrix [v]x with [v]x u = v x u.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);
// Rotation matrix of an axis-angle vector (exponential map of SO(3)).
Eigen::Matrix3d expSO3(const Eigen::Vector3d& omega);
// Left Jacobian of SO(3): Exp(w + d) = Exp(J_l(w) d) Exp(w) to first order.
Eigen::Matrix3d leftJacobianSO3(const Eigen::Vector3d& omega);

// The coefficients of Rodrigues' formula, Exp(w) = I + a [w]x + b [w]x^2 with
// a = sin(theta) / theta and b = (1 - cos(theta)) / theta^2, theta = |w|, for
// any scalar type (dual numbers included). Below theta^2 = 1e-6 they are their
// Taylor series in theta^2 (truncation below 1e-22), so value and derivatives
// stay exact at and near w = 0, where automatic differentiation evaluates updates.
template <typename T>
void rodriguesCoefficients(const T& theta2, T& a, T& b) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta2 < 1e-6) {
    a = 1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0;
    b = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
    return;
  }
  const T theta = sqrt(theta2);
  const T halfSine = sin(theta / 2.0);
  a = sin(theta) / theta;
  b = 2.0 * halfSine * halfSine / theta2;  // 1 - cos as 2 sin^2(theta / 2): no cancellation
}

// The unit quaternion of Exp(w), (cos(theta / 2), sin(theta / 2) w / theta),
// for any scalar type; a Taylor series in theta^2 below 1e-6, as above.
template <typename T>
Eigen::Quaternion<T> quaternionExp(const Eigen::Matrix<T, 3, 1>& omega) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T theta2 = omega.squaredNorm();
  T w, k;
  if (theta2 < 1e-6) {
    w = 1.0 - theta2 / 8.0 + theta2 * theta2 / 384.0;
    k = 0.5 - theta2 / 48.0 + theta2 * theta2 / 3840.0;
  } else {
    const T theta = sqrt(theta2);
    w = cos(theta / 2.0);
    k = sin(theta / 2.0) / theta;
  }
  return Eigen::Quaternion<T>(w, k * omega.x(), k * omega.y(), k * omega.z());
}

// [v]x for any scalar type.
template <typename T>
Eigen::Matrix<T, 3, 3> skewOf(const Eigen::Matrix<T, 3, 1>& v) {
  Eigen::Matrix<T, 3, 3> m;
  m << T(0.0), -v.z(), v.y(), v.z(), T(0.0), -v.x(), -v.y(), v.x(), T(0.0);
  return m;
}

// Exp(w) for any scalar type.
template <typename T>
Eigen::Matrix<T, 3, 3> expSO3Of(const Eigen::Matrix<T, 3, 1>& omega) {
  T a, b;
  rodriguesCoefficients<T>(omega.squaredNorm(), a, b);
  const Eigen::Matrix<T, 3, 3> w = skewOf(omega);
  return Eigen::Matrix<T, 3, 3>::Identity() + a * w + b * (w * w);
}

// Exp(w) x without forming the matrix, for any scalar type.
template <typename T>
Eigen::Matrix<T, 3, 1> rotateByAngleAxis(const Eigen::Matrix<T, 3, 1>& omega, const Eigen::Matrix<T, 3, 1>& x) {
  T a, b;
  rodriguesCoefficients<T>(omega.squaredNorm(), a, b);
  const Eigen::Matrix<T, 3, 1> wx = omega.cross(x);
  return x + a * wx + b * omega.cross(wx);
}

}  // namespace lrsvo
