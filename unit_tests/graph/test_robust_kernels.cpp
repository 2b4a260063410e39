// Robust kernels rho(s) on the squared norm s, Ceres' convention: values and
// weights rho'(s) against hand-computed numbers, weight = d rho / ds,
// continuity at the threshold, and an edge's cost 1/2 rho(s).

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/robust_kernel.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

constexpr const char* kKernels[] = {"Huber", "Cauchy", "Tukey"};

struct Expected {
  const char* kernel;
  double s;
  double rho;
  double weight;
};

// delta = 2, so b = delta^2 = 4. Huber: s inside b, else 2 delta sqrt(s) - b,
// weight delta / sqrt(s). Cauchy: b log(1 + s / b), weight 1 / (1 + s / b).
// Tukey: b / 3 (1 - (1 - s / b)^3), weight (1 - s / b)^2; b / 3 and 0 beyond.
constexpr Expected kExpected[] = {
    {"Huber", 0.0, 0.0, 1.0},
    {"Huber", 1.0, 1.0, 1.0},
    {"Huber", 4.0, 4.0, 1.0},
    {"Huber", 9.0, 8.0, 2.0 / 3.0},
    {"Huber", 100.0, 36.0, 0.2},
    {"Cauchy", 0.0, 0.0, 1.0},
    {"Cauchy", 4.0, 2.772588722239781, 0.5},    // 4 ln 2
    {"Cauchy", 12.0, 5.545177444479562, 0.25},  // 4 ln 4
    {"Tukey", 0.0, 0.0, 1.0},
    {"Tukey", 2.0, 7.0 / 6.0, 0.25},  // 4/3 (1 - 1/8)
    {"Tukey", 3.0, 4.0 / 3.0 * 63.0 / 64.0, 1.0 / 16.0},
    {"Tukey", 4.0, 4.0 / 3.0, 0.0},
    {"Tukey", 50.0, 4.0 / 3.0, 0.0},
};

TEST(RobustKernels, ValuesAndWeightsMatchHandComputedNumbers) {
  for (const Expected& e : kExpected) {
    const auto kernel = makeRobustKernel(e.kernel, 2.0);
    double weight = -1.0;
    const double rho = kernel->evaluate(e.s, &weight);
    EXPECT_NEAR(rho, e.rho, 1e-14 * (1.0 + e.rho)) << e.kernel << " s = " << e.s;
    EXPECT_NEAR(weight, e.weight, 1e-14) << e.kernel << " s = " << e.s;
  }
}

TEST(RobustKernels, EveryKernelIsRegisteredAndNamed) {
  for (const char* name : kKernels) {
    EXPECT_TRUE(Registry<RobustKernel>::instance().contains(name)) << name;
    const auto kernel = makeRobustKernel(name, 1.5);
    EXPECT_STREQ(kernel->name(), name);
    EXPECT_EQ(kernel->delta(), 1.5);
  }
}

// Near zero every kernel is the identity, rho(s) = s, rho'(s) = 1.
TEST(RobustKernels, QuadraticNearZero) {
  for (const char* name : kKernels) {
    const auto kernel = makeRobustKernel(name, 3.0);
    double weight = 0.0;
    const double s = 1e-8;
    EXPECT_NEAR(kernel->evaluate(s, &weight), s, 1e-15) << name;
    EXPECT_NEAR(weight, 1.0, 1e-8) << name;
  }
}

// The weight is the derivative of rho (so IRLS minimises 1/2 rho), and rho
// never decreases.
TEST(RobustKernels, WeightIsTheDerivativeOfRho) {
  constexpr double kStep = 1e-6;
  for (const char* name : kKernels) {
    for (double delta : {0.5, 1.0, 3.0}) {
      const auto kernel = makeRobustKernel(name, delta);
      const double b = delta * delta;
      double previous = -1.0;
      for (double s = 0.01 * b; s < 5.0 * b; s += 0.037 * b) {
        if (std::abs(s - b) < 10 * kStep) continue;  // the kink of Huber and Tukey
        double weight = 0.0, unused = 0.0;
        const double rho = kernel->evaluate(s, &weight);
        const double numeric =
            (kernel->evaluate(s + kStep, &unused) - kernel->evaluate(s - kStep, &unused)) / (2 * kStep);
        EXPECT_NEAR(weight, numeric, 1e-6 * (1.0 + b)) << name << " delta " << delta << " s " << s;
        EXPECT_GE(weight, 0.0) << name;
        EXPECT_LE(weight, 1.0) << name;
        EXPECT_GE(rho, previous) << name;
        EXPECT_LE(rho, s * (1.0 + 1e-15)) << name << ": a robust kernel never exceeds the squared norm";
        previous = rho;
      }
    }
  }
}

// rho and rho' are continuous where the formula changes, at s = delta^2.
TEST(RobustKernels, ContinuousAtTheThreshold) {
  for (const char* name : kKernels) {
    for (double delta : {0.5, 2.0}) {
      const auto kernel = makeRobustKernel(name, delta);
      const double b = delta * delta;
      double below = 0.0, above = 0.0;
      const double rhoBelow = kernel->evaluate(b * (1 - 1e-9), &below);
      const double rhoAbove = kernel->evaluate(b * (1 + 1e-9), &above);
      EXPECT_NEAR(rhoBelow, rhoAbove, 1e-7 * b) << name;
      EXPECT_NEAR(below, above, 1e-7) << name;
    }
  }
}

TEST(RobustKernels, InvalidDeltaOrNameIsAnError) {
  for (const char* name : kKernels)
    for (double delta : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
      EXPECT_THROW(makeRobustKernel(name, delta), Error) << name << " " << delta;
  try {
    makeRobustKernel("Welsch", 1.0);
    FAIL() << "no error";
  } catch (const Error& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("Welsch"), std::string::npos) << what;
    for (const char* name : kKernels) EXPECT_NE(what.find(name), std::string::npos) << what;
  }
}

// An edge with a kernel costs 1/2 rho(r^T Omega r).
TEST(RobustKernels, EdgeCostIsHalfRhoOfTheWhitenedSquaredNorm) {
  VertexPose pose(0);
  VertexPoint3 point(1, Eigen::Vector3d(0.2, -0.1, 5.0));
  Eigen::Matrix2d information;
  information << 2.0, 0.5, 0.5, 1.0;
  for (const char* name : {"", "Huber", "Cauchy", "Tukey"}) {
    for (double offset : {0.3, 1.0, 4.0}) {
      EdgePinhole edge;
      edge.setVertex(0, &pose);
      edge.setVertex(1, &point);
      Eigen::Vector2d prediction;
      edge.computeResidual(prediction);
      const Eigen::Vector2d r(offset, -0.5 * offset);
      edge.setMeasurement(prediction - r);
      edge.setInformation(information);
      const double s = r.dot(information * r);
      double expected = 0.5 * s;
      if (*name) {
        const auto kernel = makeRobustKernel(name, 1.5);
        edge.setRobustKernel(kernel);
        double weight;
        expected = 0.5 * kernel->evaluate(s, &weight);
      }
      EXPECT_NEAR(edge.cost(), expected, 1e-12 * expected) << name << " offset " << offset;
    }
  }
  // Spot values for delta 1.5 (b = 2.25): r = (4, -2), Omega r = (7, 0), s = 28.
  EdgePinhole edge;
  edge.setVertex(0, &pose);
  edge.setVertex(1, &point);
  Eigen::Vector2d prediction;
  edge.computeResidual(prediction);
  edge.setMeasurement(prediction - Eigen::Vector2d(4.0, -2.0));
  edge.setInformation(information);
  edge.setRobustKernel(makeRobustKernel("Huber", 1.5));
  EXPECT_NEAR(edge.cost(), 0.5 * (2 * 1.5 * std::sqrt(28.0) - 2.25), 1e-12);
  edge.setRobustKernel(makeRobustKernel("Tukey", 1.5));
  EXPECT_NEAR(edge.cost(), 0.5 * 2.25 / 3.0, 1e-12);
  edge.setRobustKernel(makeRobustKernel("Cauchy", 1.5));
  EXPECT_NEAR(edge.cost(), 0.5 * 2.25 * std::log(1.0 + 28.0 / 2.25), 1e-12);
}

}  // namespace
}  // namespace lrsvo::test
