#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lrsvo/graph/dual.h"

namespace lrsvo {

// Skew-symmetric matrix [v]x with [v]x u = v x u.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);
// Rotation matrix of an axis-angle vector (exponential map of SO(3)).
Eigen::Matrix3d expSO3(const Eigen::Vector3d& omega);
// Left Jacobian of SO(3): Exp(w + d) = Exp(J_l(w) d) Exp(w) to first order.
Eigen::Matrix3d leftJacobianSO3(const Eigen::Vector3d& omega);

// The coefficients of Rodrigues' formula, Exp(w) = I + a [w]x + b [w]x^2 with
// a = sin(theta) / theta and b = (1 - cos(theta)) / theta^2, theta = |w|, and
// their derivatives with respect to theta^2,
//   da = (cos(theta) - a) / (2 theta^2),  db = (a - 2 b) / (2 theta^2).
// Below theta^2 = 1e-6 all four are their Taylor series in theta^2 (truncation
// below 1e-22 for a and b), so values and derivatives stay exact at and near
// w = 0, where automatic differentiation evaluates updates.
struct RodriguesCoefficients {
  double a, b, da, db;
};
RodriguesCoefficients rodriguesCoefficientsAt(double theta2);

// The same for any scalar type; double and Dual share the values above, so a
// residual evaluated in duals has the same value as in double. Dual numbers
// take the closed-form derivatives in one step instead of differentiating the
// trigonometry operation by operation (half the transcendental calls and a
// tenth of the vector work).
template <typename T>
void rodriguesCoefficients(const T& theta2, T& a, T& b) {
  if constexpr (std::is_same_v<T, double>) {
    const RodriguesCoefficients c = rodriguesCoefficientsAt(theta2);
    a = c.a;
    b = c.b;
  } else if constexpr (kIsDual<T>) {
    const RodriguesCoefficients c = rodriguesCoefficientsAt(theta2.a);
    a = chainRule(c.a, c.da, theta2);
    b = chainRule(c.b, c.db, theta2);
  } else {
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
}

// The coefficients of the unit quaternion of Exp(w), (w, k w) with
// w = cos(theta / 2) and k = sin(theta / 2) / theta, and their derivatives with
// respect to theta^2, dw = -k / 4 and dk = (w / 2 - k) / (2 theta^2); Taylor
// series below theta^2 = 1e-6, as above.
struct QuaternionCoefficients {
  double w, k, dw, dk;
};
QuaternionCoefficients quaternionCoefficientsAt(double theta2);

// The unit quaternion of Exp(w) for any scalar type.
template <typename T>
Eigen::Quaternion<T> quaternionExp(const Eigen::Matrix<T, 3, 1>& omega) {
  const T theta2 = omega.squaredNorm();
  T w, k;
  if constexpr (std::is_same_v<T, double>) {
    const QuaternionCoefficients c = quaternionCoefficientsAt(theta2);
    w = c.w;
    k = c.k;
  } else if constexpr (kIsDual<T>) {
    const QuaternionCoefficients c = quaternionCoefficientsAt(theta2.a);
    w = chainRule(c.w, c.dw, theta2);
    k = chainRule(c.k, c.dk, theta2);
  } else {
    using std::cos;
    using std::sin;
    using std::sqrt;
    if (theta2 < 1e-6) {
      w = 1.0 - theta2 / 8.0 + theta2 * theta2 / 384.0;
      k = 0.5 - theta2 / 48.0 + theta2 * theta2 / 3840.0;
    } else {
      const T theta = sqrt(theta2);
      w = cos(theta / 2.0);
      k = sin(theta / 2.0) / theta;
    }
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
