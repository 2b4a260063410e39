#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/rig_deformation.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

const Vector6 kCalibration = (Vector6() << 0.7, 0.001, -0.002, 0.01, -0.02, 0.03).finished();

std::vector<double> framesAt30Hz(int count) {
  std::vector<double> times;
  for (int i = 0; i < count; ++i) times.push_back(i / 30.0);
  return times;
}

DeformationOptions still() {
  DeformationOptions options;
  options.drift.setZero();
  options.vibration.setZero();
  return options;
}

TEST(SimDeformation, ZeroAmplitudesGiveTheCalibration) {
  for (const Vector6& s : simulateDeformation(kCalibration, framesAt30Hz(100), still(), 1)) EXPECT_EQ(s, kCalibration);
}

TEST(SimDeformation, OffsetOnlyGivesCalibrationPlusOffset) {
  DeformationOptions options = still();
  options.offset << 2e-4, -1e-4, 3e-4, 0.004, -0.002, 0.001;
  for (const Vector6& s : simulateDeformation(kCalibration, framesAt30Hz(100), options, 2))
    EXPECT_TRUE(s.isApprox(kCalibration + options.offset, 1e-15));
}

TEST(SimDeformation, DriftStaysWithinItsAmplitudeAndMovesSlowly) {
  DeformationOptions options = still();
  options.drift << 3e-4, 2e-4, 1e-4, 2e-3, 1e-3, 3e-3;
  const double dt = 1.0 / 30.0;
  const std::vector<Vector6> s = simulateDeformation(kCalibration, framesAt30Hz(3000), options, 1);
  // Sinusoids with periods >= driftPeriod / 2: the rate is at most amplitude * 2 pi / (period / 2).
  const double maxRate = 2.0 * std::numbers::pi / (0.5 * options.driftPeriod_s);
  Vector6 largest = Vector6::Zero();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vector6 drift = s[i] - kCalibration;
    EXPECT_TRUE((drift.cwiseAbs().array() <= options.drift.array() + 1e-15).all()) << drift.transpose();
    largest = largest.cwiseMax(drift.cwiseAbs());
    if (i > 0) {
      const Vector6 step = (s[i] - s[i - 1]).cwiseAbs();
      EXPECT_TRUE((step.array() <= options.drift.array() * maxRate * dt + 1e-15).all()) << step.transpose();
    }
  }
  // Over 100 s (five drift periods) each parameter uses a fair part of its range.
  EXPECT_TRUE((largest.array() > 0.3 * options.drift.array()).all()) << largest.transpose();
}

TEST(SimDeformation, VibrationHasItsSigmaAndZeroMean) {
  DeformationOptions options = still();
  options.vibration << 5e-5, 1e-4, 2e-5, 2e-4, 1e-4, 3e-4;
  const std::vector<Vector6> s = simulateDeformation(kCalibration, framesAt30Hz(4000), options, 1);
  Vector6 mean = Vector6::Zero(), squares = Vector6::Zero();
  for (const Vector6& x : s) {
    mean += x - kCalibration;
    squares += (x - kCalibration).cwiseAbs2();
  }
  mean /= s.size();
  const Vector6 sigma = (squares / s.size()).cwiseSqrt();
  // 4000 draws: the sample sigma is within ~1.1 % (1 sd) of the truth, the mean within sigma / 63.
  for (int p = 0; p < 6; ++p) {
    EXPECT_NEAR(sigma[p], options.vibration[p], 0.05 * options.vibration[p]);
    EXPECT_NEAR(mean[p], 0.0, 0.06 * options.vibration[p]);
  }
}

TEST(SimDeformation, SameSeedSameDeformationOtherSeedOrCameraDifferent) {
  const DeformationOptions options;
  const std::vector<double> times = framesAt30Hz(50);
  const auto a = simulateDeformation(kCalibration, times, options, 1);
  EXPECT_EQ(a, simulateDeformation(kCalibration, times, options, 1));
  EXPECT_NE(a, simulateDeformation(kCalibration, times, options, 2));
  DeformationOptions other = options;
  other.seed = 7;
  EXPECT_NE(a, simulateDeformation(kCalibration, times, other, 1));
}

TEST(SimDeformation, BadOptionsThrow) {
  const std::vector<double> times = framesAt30Hz(3);
  EXPECT_THROW(simulateDeformation(kCalibration, times, {}, 0), Error);
  DeformationOptions options;
  options.drift[4] = -1e-3;
  EXPECT_THROW(simulateDeformation(kCalibration, times, options, 1), Error);
  options = {};
  options.vibration[0] = NAN;
  EXPECT_THROW(simulateDeformation(kCalibration, times, options, 1), Error);
  options = {};
  options.driftPeriod_s = 0.0;
  EXPECT_THROW(simulateDeformation(kCalibration, times, options, 1), Error);
  EXPECT_THROW(simulateDeformation(kCalibration, {0.0, INFINITY}, {}, 1), Error);
}

}  // namespace
}  // namespace lrsvo
