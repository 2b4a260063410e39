// The initialisation studies' flight and scoring (eval/initialization_trial).

#include <cmath>

#include <gtest/gtest.h>

#include "lrsvo/eval/initialization_trial.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

Eigen::Vector3d centre(const Eigen::Isometry3d& cameraFromWorld) { return cameraFromWorld.inverse().translation(); }

TEST(InitializationTrial, PaperSpeedRisesFrom15To50MetresPerSecond) {
  EXPECT_DOUBLE_EQ(paperSpeedForAltitude(10.0), 15.0);
  EXPECT_DOUBLE_EQ(paperSpeedForAltitude(55.0), 32.5);
  EXPECT_DOUBLE_EQ(paperSpeedForAltitude(100.0), 50.0);
  EXPECT_DOUBLE_EQ(paperSpeedForAltitude(150.0), 50.0);
}

TEST(InitializationTrial, FramesSpanSixtyMetresHighAndAQuarterFootprintLow) {
  InitializationFlight flight;
  flight.altitude_m = 100.0;
  flight.speed_m_s = 50.0;
  SimulatedSequence high = simulateSequence(initializationSimulation(flight));
  ASSERT_GE(high.trueCameraFromWorld.size(), 10u);
  // 50 m/s at 30 Hz: 1.667 m per frame, every 4th kept (6.67 m wanted): 6.67 m apart, 60 m over 10 frames.
  EXPECT_NEAR((centre(high.trueCameraFromWorld[9]) - centre(high.trueCameraFromWorld[0])).norm(), 60.0, 0.5);

  flight.altitude_m = 10.0;
  flight.speed_m_s = 15.0;
  SimulatedSequence low = simulateSequence(initializationSimulation(flight));
  // Footprint 10 m x 1024 / 1280 = 8 m; a quarter is 2 m = 4 frames of 0.5 m: 18 m over 10 frames.
  EXPECT_NEAR((centre(low.trueCameraFromWorld[9]) - centre(low.trueCameraFromWorld[0])).norm(), 18.0, 0.3);
}

TEST(InitializationTrial, RigFlexIsConstantWithinItsFractionOfTheBounds) {
  InitializationFlight flight;
  flight.flexFraction = 0.5;
  const FeatureSimulationOptions options = initializationSimulation(flight);
  EXPECT_TRUE(options.deformation.drift.isZero());
  EXPECT_FALSE(options.deformation.offset.isZero());
  for (int i = 0; i < 6; ++i) EXPECT_LE(std::abs(options.deformation.offset[i]), 0.5 * options.rig.tolerance[i]);
  EXPECT_EQ(options.deformation.offset, initializationSimulation(flight).deformation.offset);
  flight.seed = 2;
  EXPECT_NE(options.deformation.offset, initializationSimulation(flight).deformation.offset);
  flight.flexFraction = 0.0;
  EXPECT_TRUE(initializationSimulation(flight).deformation.offset.isZero());
}

TEST(InitializationTrial, ScoreMeasuresTheLastCameraInTheFirstCamerasFrame) {
  InitializationFlight flight;
  const SimulatedSequence sequence = simulateSequence(initializationSimulation(flight));
  InitializationResult exact;
  exact.success = true;
  exact.cameraFromWorld = alignToFirstCamera(sequence.trueCameraFromWorld);
  exact.cameraFromWorld.resize(10);
  const InitializationScore perfect = scoreInitialization(sequence, 10, exact);
  EXPECT_NEAR(perfect.finalPositionError_m, 0.0, 1e-9);
  EXPECT_NEAR(perfect.scaleRatio, 1.0, 1e-12);
  // 30 m/s at 30 Hz: 1 m per frame, every 7th kept for the 6.67 m wanted: 9 x 7 m.
  EXPECT_NEAR(perfect.distanceFlown_m, 63.0, 1e-6);

  // The map 1.5 times too large about the first camera: the last camera is
  // half the distance flown off and the scale error is 2/3.
  InitializationResult scaledUp = exact;
  for (Eigen::Isometry3d& pose : scaledUp.cameraFromWorld) pose.translation() *= 1.5;
  const InitializationScore scaled = scoreInitialization(sequence, 10, scaledUp);
  EXPECT_NEAR(scaled.finalPositionError_m, 0.5 * perfect.distanceFlown_m, 1e-9);
  EXPECT_NEAR(scaled.scaleRatio, 2.0 / 3.0, 1e-12);

  // Three times too large: two distances off, limited to one (the paper's limit).
  for (Eigen::Isometry3d& pose : scaledUp.cameraFromWorld) pose.translation() *= 2.0;
  const InitializationScore far = scoreInitialization(sequence, 10, scaledUp);
  EXPECT_NEAR(far.rawFinalPositionError_m, 2.0 * perfect.distanceFlown_m, 1e-9);
  EXPECT_DOUBLE_EQ(far.finalPositionError_m, far.distanceFlown_m);

  // A run that failed by its own verdict scores the limit, whatever it returned.
  InitializationResult unsound = exact;
  unsound.success = false;
  EXPECT_DOUBLE_EQ(scoreInitialization(sequence, 10, unsound).finalPositionError_m, perfect.distanceFlown_m);

  // A run that stopped early scores the distance flown, the paper's limit.
  InitializationResult stopped = exact;
  stopped.success = false;
  stopped.cameraFromWorld.resize(4);
  const InitializationScore early = scoreInitialization(sequence, 10, stopped);
  EXPECT_FALSE(early.reachedEnd);
  EXPECT_DOUBLE_EQ(early.finalPositionError_m, early.distanceFlown_m);
  EXPECT_THROW(scoreInitialization(sequence, 1000, exact), Error);
}

TEST(InitializationTrial, BadFlightsAreErrors) {
  InitializationFlight flight;
  flight.frames = 2;
  EXPECT_THROW(initializationSimulation(flight), Error);
  flight = {};
  flight.altitude_m = -5.0;
  EXPECT_THROW(initializationSimulation(flight), Error);
}

}  // namespace
}  // namespace lrsvo
