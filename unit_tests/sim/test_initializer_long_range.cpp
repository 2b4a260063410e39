#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/long_range_initializer.h"
#include "lrsvo/frontend/odometry/monocular_initializer.h"
#include "unit_tests/initializer_flight.h"

// Measured on initializationFlight (unit_tests/initializer_flight.h) at
// 100 m, seeds 1-5, log barrier: final camera position errors 0.28, 0.71,
// 1.84, 1.66, 3.27 m (0.5-5.5 % of the 60 m flown; RMS 3.1 %), with the
// scale's relative standard deviation from the information 3.5-3.9 %. The
// error is the statistical one the information allows: a pitch error of the
// secondary camera shifts every disparity alike (1.7 px per mrad against
// 11.7 px of disparity at 100 m) and only the terrain's depth variation tells
// it from a change of scale (1000 features per frame instead of 300 gave
// 2.4 %). Hence the tolerance: within 3 of those standard deviations, and
// within the paper's 5 m at 100 m (Fig. 17). From half the true scale the
// batch ends at the same optimum with kappa and without: the log barrier cuts
// a step that would leave the box short rather than rejecting it, so it does
// not stall in the flat valley between the secondary camera's pitch and the
// scale (gradient projection without kappa does, test_scale_init.cpp).

namespace lrsvo::test {
namespace {

TEST(InitializerLongRange, RecoversMetricScaleAndExtrinsicAt100m) {
  const SimulatedSequence sequence = initializationFlight(100.0, 1);
  const InitializationResult result = LongRangeInitializer({}).initialize(sequence.rig, sequence.frames);
  ASSERT_TRUE(result.success) << result.failure;
  ASSERT_EQ(result.cameraFromWorld.size(), 10u);
  EXPECT_TRUE(result.cameraFromWorld[0].isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  const double flown = distanceFlown(sequence, 10);
  const double error = finalPositionError(result, sequence);
  EXPECT_LT(error, 3.0 * result.kappaRelativeStd * flown);
  EXPECT_LT(error, 5.0);
  EXPECT_GT(result.kappaRelativeStd, 0.01);  // the information is finite: a 0 would mean a gauge was missed
  EXPECT_LT(result.kappaRelativeStd, 0.06);
  // kappa is the first pair's distance in metres (initialBaseline = 1).
  const double firstPair = distanceFlown(sequence, 2);
  EXPECT_NEAR(result.kappa, firstPair, 3.0 * result.kappaRelativeStd * firstPair);
  EXPECT_LT(result.rmsReprojectionError_px, 1.1);  // 1 px noise per coordinate

  // The extrinsic stays inside the rig's box, and its pitch, the parameter
  // that trades off against scale, lands near the truth (within 1 mrad).
  const auto& calibrated = sequence.rig.extrinsics[0];
  for (int i = 0; i < 6; ++i) {
    EXPECT_GE(result.extrinsics[0][i], calibrated[i] - sequence.rig.tolerance[i] - 1e-9) << "parameter " << i;
    EXPECT_LE(result.extrinsics[0][i], calibrated[i] + sequence.rig.tolerance[i] + 1e-9) << "parameter " << i;
  }
  double truePitch = 0.0;
  for (const auto& extrinsics : sequence.trueExtrinsics) truePitch += extrinsics[0][4] / 10.0;
  EXPECT_NEAR(result.extrinsics[0][4], truePitch, 1e-3);
}

// With and without kappa the batch is the same model up to the gauge kappa
// adds, so from half the true scale both must end at one optimum. Tolerances:
// each stops when a step changes the cost by at most 1e-6 of it; allowing
// ten times that between their final costs (0.036 of 3600) allows the scale
// sqrt(2 x 0.036) = 0.27 of its own standard deviation apart.
TEST(InitializerLongRange, FromHalfTheScaleWithAndWithoutKappaReachTheSameOptimum) {
  const SimulatedSequence sequence = initializationFlight(100.0, 1);
  LongRangeInitializerOptions options;
  options.initialBaseline = 0.5 * distanceFlown(sequence, 2);  // start scale 0.5
  const InitializationResult withKappa = LongRangeInitializer(options).initialize(sequence.rig, sequence.frames);
  options.estimateScale = false;
  const InitializationResult withoutKappa = LongRangeInitializer(options).initialize(sequence.rig, sequence.frames);
  ASSERT_TRUE(withKappa.success) << withKappa.failure;
  ASSERT_TRUE(withoutKappa.success) << withoutKappa.failure;
  // kappa finds the map's unit: twice the first pair's distance in map units.
  EXPECT_NEAR(withKappa.kappa * options.initialBaseline, distanceFlown(sequence, 2),
              3.0 * withKappa.kappaRelativeStd * distanceFlown(sequence, 2));
  EXPECT_NEAR(withoutKappa.summary.finalCost, withKappa.summary.finalCost, 1e-5 * withKappa.summary.finalCost);
  const double flown = distanceFlown(sequence, 10);
  const auto lastCentre = [](const InitializationResult& r) -> Eigen::Vector3d {
    return r.cameraFromWorld.back().inverse().translation();
  };
  EXPECT_LT((lastCentre(withKappa) - lastCentre(withoutKappa)).norm(), 0.3 * withKappa.kappaRelativeStd * flown);
}

TEST(InitializerLongRange, MonocularMapHasTheRightShapeAtUnitScale) {
  const SimulatedSequence sequence = initializationFlight(100.0, 2);
  MonocularOptions options;
  options.initialBaseline = 2.0;
  const MonocularResult mono = buildMonocularMap(sequence.rig, sequence.frames, options);
  ASSERT_TRUE(mono.success) << mono.failure;
  const auto& poses = mono.map.cameraFromWorld;
  ASSERT_EQ(poses.size(), 10u);
  EXPECT_NEAR((poses[1].inverse().translation() - poses[0].inverse().translation()).norm(), 2.0, 1e-9);
  // Scaled to the truth by the first pair, every camera lies within 10 % of
  // the first pair's 6.7 m of where it should (measured: < 2 %).
  const std::vector<Eigen::Isometry3d> truth = alignToFirstCamera(sequence.trueCameraFromWorld);
  const double toMetres = distanceFlown(sequence, 2) / 2.0;
  for (std::size_t i = 0; i < poses.size(); ++i)
    EXPECT_LT((toMetres * poses[i].inverse().translation() - truth[i].inverse().translation()).norm(),
              0.1 * distanceFlown(sequence, 2) + 0.02 * distanceFlown(sequence, i + 1))
        << "frame " << i;
}

TEST(InitializerLongRange, SameSeedSameResult) {
  const SimulatedSequence sequence = initializationFlight(70.0, 3);
  LongRangeInitializerOptions options;
  options.constraintMethod = "gradient_projection";
  const InitializationResult first = LongRangeInitializer(options).initialize(sequence.rig, sequence.frames);
  const InitializationResult second = LongRangeInitializer(options).initialize(sequence.rig, sequence.frames);
  ASSERT_TRUE(first.success) << first.failure;
  ASSERT_EQ(first.cameraFromWorld.size(), second.cameraFromWorld.size());
  for (std::size_t i = 0; i < first.cameraFromWorld.size(); ++i)
    EXPECT_TRUE(first.cameraFromWorld[i].isApprox(second.cameraFromWorld[i], 0.0)) << "frame " << i;
  EXPECT_EQ(first.kappa, second.kappa);
  EXPECT_EQ(first.extrinsics[0], second.extrinsics[0]);
}

// Over flat ground (no relief, trees or buildings) the pair's essential matrix may
// settle on the planar twin, which flies along the ground's normal; its map then ends
// more than half the distance flown from the truth. The homography's true motion is
// the other hypothesis, and the secondary camera, which fits the true motion only,
// picks it. Which RANSAC draws land on the twin depends on the simulated pixels'
// last bits (the compiler's rounding); with one RANSAC run instead of the best of
// five the twin is common on this flat world, and the first of 20 seeds that lands
// on it is the case.
TEST(InitializerLongRange, SecondaryCameraRejectsThePlanarTwin) {
  FeatureSimulationOptions simulation = initializationFlightOptions(60.0, 10);
  simulation.terrain.relief_m = 0.0;
  simulation.terrain.treeDensity_per_km2 = 0.0;
  simulation.terrain.buildingDensity_per_km2 = 0.0;
  const SimulatedSequence sequence = simulateSequence(simulation);
  const double flown = distanceFlown(sequence, 10);
  const std::vector<Eigen::Isometry3d> truth = alignToFirstCamera(sequence.trueCameraFromWorld);
  const double toMetres = distanceFlown(sequence, 2);  // the maps' unit: frames 0 and 1 are 1 apart
  const auto endError = [&](const MonocularResult& map) {
    return (toMetres * map.map.cameraFromWorld[9].inverse().translation() - truth[9].inverse().translation()).norm();
  };

  LongRangeInitializerOptions options;
  options.monocular.twoView.attempts = 1;
  std::vector<MonocularResult> maps;
  for (options.seed = 1; options.seed <= 20; ++options.seed) {
    maps = buildMonocularMaps(sequence.rig, sequence.frames, LongRangeInitializer(options).monocularOptions());
    ASSERT_TRUE(maps[0].success) << "seed " << options.seed << ": " << maps[0].failure;
    if (endError(maps[0]) > 0.5 * flown) break;  // the essential matrix's twin
  }
  ASSERT_LE(options.seed, 20u) << "no RANSAC seed settled on the twin";
  const bool trueMotionAmongTheOthers = std::any_of(maps.begin() + 1, maps.end(), [&](const MonocularResult& map) {
    return map.success && endError(map) < 0.05 * flown;
  });
  EXPECT_TRUE(trueMotionAmongTheOthers) << "seed " << options.seed;

  const InitializationResult result = LongRangeInitializer(options).initialize(sequence.rig, sequence.frames);
  ASSERT_TRUE(result.success) << result.failure;
  EXPECT_LT(finalPositionError(result, sequence), 3.0 * result.kappaRelativeStd * flown) << "seed " << options.seed;
}

// A few observations that are no projection of their point (3 % replaced by
// a uniform random pixel, in both cameras) would put the RMS the checks read
// far past the noise: the batch leaves the outliers out and runs again, so
// what remains fits as the 1 px noise does, and the start is as good as the
// information allows, on every seed of a batch.
TEST(InitializerLongRange, LeavesOutliersOutAndStartsAsWithoutThem) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(seed);
    FeatureSimulationOptions options = initializationFlightOptions(100.0, seed);
    options.outlierFraction = 0.03;
    const SimulatedSequence sequence = simulateSequence(options);
    const InitializationResult result = LongRangeInitializer({}).initialize(sequence.rig, sequence.frames);
    ASSERT_TRUE(result.success) << result.failure;
    EXPECT_LT(result.rmsReprojectionError_px, 1.1);  // 1 px noise per coordinate
    EXPECT_LT(finalPositionError(result, sequence), 3.0 * result.kappaRelativeStd * distanceFlown(sequence, 10));
  }
}

// Of two starts from the same frames, one that passes its checks wins over
// one that fails them, however well the failing one fits (the planar twin
// with kappa grown without bound fits well and fails the conditioning check);
// between two alike, the lower RMS wins.
TEST(InitializerLongRange, PrefersAStartThatPassesItsChecks) {
  InitializationResult passes, fails;
  passes.success = true;
  passes.rmsReprojectionError_px = 1.0;
  fails.rmsReprojectionError_px = 0.4;
  EXPECT_TRUE(isBetterStart(passes, fails));
  EXPECT_FALSE(isBetterStart(fails, passes));
  InitializationResult passesBetter = passes;
  passesBetter.rmsReprojectionError_px = 0.9;
  EXPECT_TRUE(isBetterStart(passesBetter, passes));
  EXPECT_FALSE(isBetterStart(passes, passesBetter));
  EXPECT_FALSE(isBetterStart(passes, passes));
}

TEST(InitializerLongRange, ReportsWhyItFails) {
  // 20 m up, the 15 m footprint spans two frames 6.7 m apart but never
  // three: nothing mapped from the pair is seen by the next frame.
  const SimulatedSequence low = initializationFlight(20.0, 1);
  const InitializationResult result = LongRangeInitializer({}).initialize(low.rig, low.frames);
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.failure.find("mapped points"), std::string::npos) << result.failure;
  EXPECT_TRUE(result.cameraFromWorld.empty());  // no metric scale without the batch

  const SimulatedSequence sequence = initializationFlight(100.0, 1);
  const std::vector<FrameObservations> five(sequence.frames.begin(), sequence.frames.begin() + 5);
  EXPECT_NE(LongRangeInitializer({}).initialize(sequence.rig, five).failure.find("5 frames given"), std::string::npos);
  LongRangeInitializerOptions unknown;
  unknown.constraintMethod = "no_such_method";
  EXPECT_THROW(LongRangeInitializer{unknown}, Error);
}

}  // namespace
}  // namespace lrsvo::test
