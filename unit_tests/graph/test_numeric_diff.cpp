// Numeric differences with relative steps (graph/numeric_diff.h) on a badly
// scaled residual, against its exact dual-number Jacobian.

#include <cmath>

#include <gtest/gtest.h>

#include "lrsvo/graph/autodiff_edge.h"

namespace lrsvo::test {
namespace {

class VertexThreeScales : public VectorVertex<3> {
 public:
  using VectorVertex<3>::VectorVertex;
  const char* typeTag() const override { return "TEST_THREE_SCALES"; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexThreeScales>(*this); }
};

// Parameters of three scales, b = (6e-9, 0.7, 6e3), one residual each:
// r = (exp(b1 / 1e-8), sin(b2), b3^2 / 1e7). An absolute step of 1e-6 would
// be 166 times b1 (and the exponential's curvature scale 1e-8) and fail outright.
class EdgeThreeScales : public AutoDiffEdge<EdgeThreeScales, 3, VertexThreeScales> {
 public:
  explicit EdgeThreeScales(NumericDiffOptions options) : options_(options) {}
  const char* typeTag() const override { return "TEST_THREE_SCALES_EDGE"; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 3, 1>& b, Eigen::Matrix<T, 3, 1>& r) const {
    using std::exp;
    using std::sin;
    r << exp(b[0] / 1e-8), sin(b[1]), b[2] * b[2] / 1e7;
  }
  NumericDiffOptions numericDiffOptions() const override { return options_; }

 private:
  NumericDiffOptions options_;
};

// Largest relative error of the numeric Jacobian's diagonal (the off-diagonal
// entries are zero in both: each residual reads one parameter).
double worstRelativeError(NumericDifference method) {
  VertexThreeScales b(0);
  b.setEstimateVector(Eigen::Vector3d(6e-9, 0.7, 6e3));
  EdgeThreeScales edge(NumericDiffOptions{.method = method, .typicalMagnitude = 0.0});
  edge.setVertex(0, &b);
  edge.computeAutoDiffJacobians();
  const Eigen::Matrix3d exact = edge.jacobian<0>();
  edge.computeNumericJacobians();
  const Eigen::Matrix3d numeric = edge.jacobian<0>();
  EXPECT_EQ((numeric - Eigen::Matrix3d(numeric.diagonal().asDiagonal())).norm(), 0.0);
  return ((numeric - exact).diagonal().array() / exact.diagonal().array()).abs().maxCoeff();
}

// The bounds (docs/autodiff.md), relative to |r'| with h = s |x|:
//   forward:  h |r''| / 2 + 2 eps |r| / h. The exponential is worst: |r''/r'| = 1e8 and
//             h = 1.5e-8 * 6e-9, so 4.5e-9, plus 2 * 2.2e-16 * 1.8 / 9e-17 / 1.8e8 = 4.9e-8.
//   central:  h^2 |r'''| / 6 + eps |r| / h. Exponential: (3.6e-14)^2 / 6 / 1e-16 = 2e-12
//             plus 2.2e-16 * 1.8 / 3.6e-14 / 1.8e8 = 6e-11; sine: s^2 / 6 = 6e-12; the
//             square has r''' = 0 and rounding 2e-11.
//   Ridders:  extrapolates the central error away; rounding at its last step remains.
// The limits below are those bounds times ten or more.
TEST(NumericDiff, RelativeStepsDifferentiateBadlyScaledParameters) {
  EXPECT_LT(worstRelativeError(NumericDifference::kForward), 1e-6);
  EXPECT_LT(worstRelativeError(NumericDifference::kCentral), 1e-9);
  EXPECT_LT(worstRelativeError(NumericDifference::kRidders), 1e-9);
}

// Ridders' extrapolation reaches well below plain central differences on a
// residual with large higher derivatives at a unit step.
TEST(NumericDiff, RiddersExtrapolatesBelowCentralDifferences) {
  VertexThreeScales b(0);
  b.setEstimateVector(Eigen::Vector3d(6e-9, 0.7, 6e3));
  const auto errorOf = [&](NumericDiffOptions options) {
    EdgeThreeScales edge(options);
    edge.setVertex(0, &b);
    edge.computeAutoDiffJacobians();
    const double exact = edge.jacobian<0>()(1, 1);
    edge.computeNumericJacobians();
    return std::abs(edge.jacobian<0>()(1, 1) - exact) / std::abs(exact);
  };
  // sin at h = 0.1 |0.7|: central errs by h^2 / 6 = 8e-5; Ridders starting there gets below 1e-10.
  EXPECT_GT(errorOf({.method = NumericDifference::kCentral, .relativeStep = 0.1, .typicalMagnitude = 0.0}), 1e-5);
  EXPECT_LT(errorOf({.method = NumericDifference::kRidders, .relativeStep = 0.1, .typicalMagnitude = 0.0}), 1e-10);
}

TEST(NumericDiff, DefaultStepsAreTheMethodsOptima) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  EXPECT_EQ(NumericDiffOptions{.method = NumericDifference::kForward}.step(), std::sqrt(eps));
  EXPECT_EQ(NumericDiffOptions{.method = NumericDifference::kCentral}.step(), std::cbrt(eps));
  EXPECT_EQ((NumericDiffOptions{.method = NumericDifference::kCentral, .relativeStep = 1e-4}.step()), 1e-4);
}

}  // namespace
}  // namespace lrsvo::test
