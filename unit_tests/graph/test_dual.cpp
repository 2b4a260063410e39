// lrsvo's dual numbers (graph/dual.h) against Eigen's AutoDiffScalar, an
// independent forward-mode implementation, on every operation and function.
//
// Both evaluate the same chain rule in double, each operation rounding to
// within half an ulp of its own result; over the few operations of each
// expression below the two can differ by a few ulps of the largest term, so
// they must agree to 1e-14 relative (about 45 ulps).

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "lrsvo/graph/dual.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo::test {
namespace {

constexpr int kN = 3;
using Ours = Dual<kN>;
using Reference = Eigen::AutoDiffScalar<Eigen::Matrix<double, kN, 1>>;
constexpr double kAgreement = 1e-14;

// One expression per operation, the same code for both types.
template <typename T>
Eigen::Matrix<T, 20, 1> everyOperation(const T& x, const T& y, const T& z) {
  using std::abs;
  using std::acos;
  using std::asin;
  using std::atan2;
  using std::cos;
  using std::exp;
  using std::log;
  using std::pow;
  using std::sin;
  using std::sqrt;
  using std::tan;
  Eigen::Matrix<T, 20, 1> out;
  T compound = x;
  compound *= y;
  compound += z;
  compound /= y;
  compound -= 0.5 * x;
  out << x + y, x - y, x * y, x / y, 2.0 + x, 2.0 - x, 3.0 * x, 3.0 / y, -x, sqrt(y), exp(x), log(y), sin(x), cos(x),
      tan(x), atan2(x, y), pow(y, 1.7), abs(z), compound, asin(x / 4.0) + acos(x / 4.0) * z;
  return out;
}

TEST(Dual, EveryOperationAgreesWithEigensAutoDiffScalar) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double x = uniform(random), y = 2.5 + uniform(random), z = uniform(random);
    const auto ours = everyOperation(Ours::variable(x, 0), Ours::variable(y, 1), Ours::variable(z, 2));
    const auto reference = everyOperation(Reference(x, kN, 0), Reference(y, kN, 1), Reference(z, kN, 2));
    for (int k = 0; k < ours.size(); ++k) {
      const double scale = std::max(1.0, std::abs(reference[k].value()));
      EXPECT_NEAR(ours[k].value(), reference[k].value(), kAgreement * scale) << "operation " << k;
      const double derivativeScale = std::max(1.0, reference[k].derivatives().norm());
      EXPECT_LE((ours[k].derivatives() - reference[k].derivatives()).norm(), kAgreement * derivativeScale)
          << "operation " << k << " at x=" << x << " y=" << y << " z=" << z;
    }
  }
}

// Eigen's AutoDiffScalar has no atan: ours against its derivative 1 / (1 + z^2).
TEST(Dual, ArcTangentHasItsDerivative) {
  for (const double z : {-3.0, -0.2, 0.0, 0.7, 40.0}) {
    const Ours a = atan(Ours::variable(z, 1));
    EXPECT_DOUBLE_EQ(a.value(), std::atan(z));
    EXPECT_DOUBLE_EQ(a.derivatives()[1], 1.0 / (1.0 + z * z));
    EXPECT_EQ(a.derivatives()[0], 0.0);
  }
}

TEST(Dual, EigenMatricesOfDualsMultiplyWithDoubleMatrices) {
  const Eigen::Matrix3d a = (Eigen::Matrix3d() << 1, 2, 3, 4, 5, 6, 7, 8, 10).finished();
  Eigen::Matrix<Ours, 3, 1> v;
  v << Ours::variable(1.0, 0), Ours::variable(-2.0, 1), Ours::variable(0.5, 2);
  const Eigen::Matrix<Ours, 3, 1> product = a.cast<Ours>() * v;
  for (int row = 0; row < 3; ++row) {
    EXPECT_DOUBLE_EQ(product[row].value(), a.row(row).dot(Eigen::Vector3d(1.0, -2.0, 0.5)));
    // d(A v)/dv = A, exactly: each derivative is a sum of integer products.
    EXPECT_EQ(product[row].derivatives(), a.row(row).transpose());
  }
  const Ours norm = v.norm();
  EXPECT_DOUBLE_EQ(norm.value(), std::sqrt(5.25));
}

// The rotation coefficients (vertices/so3.h) give duals closed-form
// derivatives; AutoDiffScalar differentiates the same formulas operation by
// operation. Above the Taylor switch both derivatives cancel: d a / d w is
// (theta cos(theta) - sin(theta)) / theta^2 times w / theta, a difference of
// terms of size theta computed to a few eps theta, so each is off by a few
// eps / theta (2e-12 at the switch, theta = 1e-3). Values and the Taylor region
// keep the 1e-14 of the other operations.
template <typename T>
Eigen::Matrix<T, 6, 1> rotationCoefficients(const Eigen::Matrix<T, 3, 1>& omega) {
  T a, b;
  rodriguesCoefficients(T(omega.squaredNorm()), a, b);
  const Eigen::Quaternion<T> q = quaternionExp(omega);
  Eigen::Matrix<T, 6, 1> out;
  out << a, b, q.w(), q.x(), q.y(), q.z();
  return out;
}

TEST(Dual, RotationCoefficientsHaveTheirDerivatives) {
  std::mt19937_64 random(8);
  std::normal_distribution<double> normal(0.0, 1.0);
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  for (const double theta : {0.0, 1e-5, 9e-4, 1.1e-3, 0.1, 1.0, 3.0}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Vector3d omega =
          theta * Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
      Eigen::Matrix<Ours, 3, 1> oursOmega;
      Eigen::Matrix<Reference, 3, 1> referenceOmega;
      for (int i = 0; i < 3; ++i) {
        oursOmega[i] = Ours::variable(omega[i], i);
        referenceOmega[i] = Reference(omega[i], kN, i);
      }
      const auto ours = rotationCoefficients(oursOmega);
      const auto reference = rotationCoefficients(referenceOmega);
      const double derivativeAgreement = kAgreement + (theta * theta >= 1e-6 ? 10.0 * kEpsilon / theta : 0.0);
      for (int k = 0; k < ours.size(); ++k) {
        EXPECT_NEAR(ours[k].value(), reference[k].value(), kAgreement) << "coefficient " << k << " theta " << theta;
        EXPECT_LE((ours[k].derivatives() - reference[k].derivatives()).cwiseAbs().maxCoeff(), derivativeAgreement)
            << "coefficient " << k << " theta " << theta;
      }
    }
  }
}

TEST(Dual, ComparisonsReadTheValuesOnly) {
  const Ours small = Ours::variable(1.0, 0), large(2.0);
  EXPECT_TRUE(small < large);
  EXPECT_TRUE(small <= 1.0);
  EXPECT_TRUE(3.0 > large);
  EXPECT_TRUE(small == 1.0);
  EXPECT_TRUE(small != large);
  EXPECT_TRUE(isfinite(small));
  EXPECT_FALSE(isfinite(Ours(std::nan(""))));
}

}  // namespace
}  // namespace lrsvo::test
