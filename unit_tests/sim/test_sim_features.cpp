#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/feature_simulator.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

// A short level flight over the default world, exact measurements.
FeatureSimulationOptions shortFlight() {
  FeatureSimulationOptions options;
  options.flight.speed_m_s = 30.0;
  options.flight.frameStep = 3;
  options.flight.legs = {{FlightLeg::Kind::Straight, 30.0}};
  options.points = 1500;
  options.pixelNoise_px = 0.0;
  return options;
}

std::map<int, std::vector<int>> framesPerTrack(const SimulatedSequence& sequence) {
  std::map<int, std::vector<int>> frames;
  for (std::size_t i = 0; i < sequence.frames.size(); ++i)
    for (const Observation& o : sequence.frames[i].observations)
      if (o.camera == 0) frames[o.track].push_back(static_cast<int>(i));
  return frames;
}

TEST(SimFeatures, FrameZeroProjectsLikeTheHandWrittenStereoModel) {
  FeatureSimulationOptions options = shortFlight();
  options.deformation.drift.setZero();
  options.deformation.vibration.setZero();
  const double yaw = 0.01;
  options.deformation.offset << 0.0, 0.0, 0.0, 0.0, 0.0, yaw;
  const SimulatedSequence sequence = simulateSequence(options);
  const double f = options.rig.cameras[0].intrinsics.fx, cx = 640.0, cy = 480.0, h = 100.0;
  EXPECT_TRUE(sequence.trueExtrinsics[0][0].isApprox((Vector6() << 0.7, 0, 0, 0, 0, yaw).finished()));
  // Frame 0: base camera at (0, 0, 100) with x along world x and z down, so a
  // world point (X, Y, Z) is at (X, -Y, 100 - Z) in the base camera; the
  // secondary sees Rz(yaw) ((X, -Y, 100 - Z) - (0.7, 0, 0)).
  ASSERT_FALSE(sequence.frames[0].observations.empty());
  int secondary = 0;
  for (std::size_t n = 0; n < sequence.frames[0].observations.size(); ++n) {
    const Observation& o = sequence.frames[0].observations[n];
    const Eigen::Vector3d& p = sequence.truePoints[o.track];
    double x = p.x(), y = -p.y();
    const double z = h - p.z();
    if (o.camera == 1) {
      x -= 0.7;
      const double xr = std::cos(yaw) * x - std::sin(yaw) * y, yr = std::sin(yaw) * x + std::cos(yaw) * y;
      x = xr;
      y = yr;
      ++secondary;
    }
    EXPECT_NEAR(o.pixel.x(), f * x / z + cx, 1e-9);
    EXPECT_NEAR(o.pixel.y(), f * y / z + cy, 1e-9);
    EXPECT_EQ(o.pixel, sequence.truePixels[0][n]);
  }
  EXPECT_GT(secondary, 100);
}

TEST(SimFeatures, ExactObservationsAreEveryVisibleProjectionAndNothingElse) {
  FeatureSimulationOptions options = shortFlight();
  options.imageMargin_px = 15.0;
  const SimulatedSequence sequence = simulateSequence(options);
  ASSERT_EQ(sequence.frames.size(), 11u);
  for (std::size_t i = 0; i < sequence.frames.size(); ++i) {
    // Brute force over every point and camera, independent of the simulator's spatial grid.
    std::vector<Observation> expected;
    for (std::size_t j = 0; j < sequence.truePoints.size(); ++j) {
      for (int k = 0; k < 2; ++k) {
        const Eigen::Vector3d c = trueCameraPose(sequence, static_cast<int>(i), k) * sequence.truePoints[j];
        const Eigen::Vector2d pixel = options.rig.cameras[k].intrinsics.project(c);
        if (c.z() > 0.0 && options.rig.cameras[k].inImage(pixel, 15.0))
          expected.push_back({static_cast<int>(j), k, pixel});
      }
    }
    const std::vector<Observation>& got = sequence.frames[i].observations;
    ASSERT_EQ(got.size(), expected.size()) << "frame " << i;
    for (std::size_t n = 0; n < got.size(); ++n) {
      EXPECT_EQ(got[n].track, expected[n].track);
      EXPECT_EQ(got[n].camera, expected[n].camera);
      EXPECT_TRUE(got[n].pixel.isApprox(expected[n].pixel, 1e-12));
      EXPECT_FALSE(sequence.outlier[i][n]);
    }
  }
}

TEST(SimFeatures, PixelNoiseHasItsSigma) {
  FeatureSimulationOptions options = shortFlight();
  options.pixelNoise_px = 1.5;
  const SimulatedSequence sequence = simulateSequence(options);
  double sum = 0.0, squares = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < sequence.frames.size(); ++i) {
    for (std::size_t n = 0; n < sequence.frames[i].observations.size(); ++n) {
      const Eigen::Vector2d e = sequence.frames[i].observations[n].pixel - sequence.truePixels[i][n];
      sum += e.sum();
      squares += e.squaredNorm();
      count += 2;
    }
  }
  ASSERT_GT(count, 10000);
  EXPECT_NEAR(std::sqrt(squares / count), 1.5, 0.05);
  EXPECT_NEAR(sum / count, 0.0, 0.05);
}

TEST(SimFeatures, SameSeedSameSequenceOtherSeedOtherPointsAndNoise) {
  FeatureSimulationOptions options = shortFlight();
  options.pixelNoise_px = 1.0;
  options.outlierFraction = 0.05;
  const SimulatedSequence a = simulateSequence(options), b = simulateSequence(options);
  EXPECT_EQ(a.truePoints, b.truePoints);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    ASSERT_EQ(a.frames[i].observations.size(), b.frames[i].observations.size());
    for (std::size_t n = 0; n < a.frames[i].observations.size(); ++n)
      EXPECT_EQ(a.frames[i].observations[n].pixel, b.frames[i].observations[n].pixel);
    EXPECT_EQ(a.trueExtrinsics[i], b.trueExtrinsics[i]);
    EXPECT_EQ(a.outlier[i], b.outlier[i]);
  }
  options.seed = 2;
  const SimulatedSequence c = simulateSequence(options);
  EXPECT_NE(a.truePoints, c.truePoints);
  // The flight and the deformation have their own seeds: same path, same rig motion.
  EXPECT_TRUE(a.trueCameraFromWorld.back().isApprox(c.trueCameraFromWorld.back(), 0.0));
  EXPECT_EQ(a.trueExtrinsics, c.trueExtrinsics);
}

TEST(SimFeatures, OutliersAreMarkedUniformPixelsAtTheirRateAndLeaveTheOtherMeasurementsAlone) {
  FeatureSimulationOptions options = shortFlight();
  options.pixelNoise_px = 1.0;
  const SimulatedSequence clean = simulateSequence(options);
  options.outlierFraction = 0.2;
  const SimulatedSequence sequence = simulateSequence(options);
  int outliers = 0, total = 0;
  for (std::size_t i = 0; i < sequence.frames.size(); ++i) {
    ASSERT_EQ(sequence.frames[i].observations.size(), clean.frames[i].observations.size());
    for (std::size_t n = 0; n < sequence.frames[i].observations.size(); ++n) {
      const Observation& o = sequence.frames[i].observations[n];
      ++total;
      if (sequence.outlier[i][n]) {
        ++outliers;
        EXPECT_TRUE(options.rig.cameras[o.camera].inImage(o.pixel));
      } else {
        // Outliers draw from their own stream: every other measurement keeps its noise.
        EXPECT_EQ(o.pixel, clean.frames[i].observations[n].pixel);
      }
    }
  }
  ASSERT_GT(total, 5000);
  EXPECT_NEAR(static_cast<double>(outliers) / total, 0.2, 0.02);
}

TEST(SimFeatures, DroppedTracksEndForGoodAndKeepTheirEarlierFrames) {
  FeatureSimulationOptions options = shortFlight();
  const std::map<int, std::vector<int>> full = framesPerTrack(simulateSequence(options));
  options.dropProbability = 0.1;
  const std::map<int, std::vector<int>> dropped = framesPerTrack(simulateSequence(options));
  std::size_t fullCount = 0, droppedCount = 0;
  for (const auto& [track, frames] : full) {
    fullCount += frames.size();
    const auto found = dropped.find(track);
    if (found == dropped.end()) continue;
    // The same points, so a dropped track's frames are the first ones of its full track.
    ASSERT_LE(found->second.size(), frames.size());
    EXPECT_TRUE(std::equal(found->second.begin(), found->second.end(), frames.begin()));
    droppedCount += found->second.size();
  }
  // Each sighting survives with probability 0.9: far fewer observations in all.
  EXPECT_LT(droppedCount, 0.8 * fullCount);
  EXPECT_GT(droppedCount, 0.2 * fullCount);
  options.dropProbability = 1.0;
  EXPECT_TRUE(framesPerTrack(simulateSequence(options)).empty());
}

TEST(SimFeatures, PointsPerFrameHoldsTheBaseCameraCountSteadyOverAltitude) {
  for (double altitude : {20.0, 120.0}) {
    FeatureSimulationOptions options = shortFlight();
    options.flight.altitude_m = altitude;
    options.pointsPerFrame = 300;
    const SimulatedSequence sequence = simulateSequence(options);
    double base = 0.0;
    for (const FrameObservations& frame : sequence.frames)
      for (const Observation& o : frame.observations) base += o.camera == 0 ? 1.0 : 0.0;
    EXPECT_NEAR(base / sequence.frames.size(), 300.0, 45.0) << "altitude " << altitude;
  }
}

TEST(SimFeatures, ThreeCameraRigGetsOneDeformingExtrinsicPerSecondary) {
  FeatureSimulationOptions options = shortFlight();
  options.rig.cameras.push_back(options.rig.cameras[0]);
  options.rig.extrinsics.push_back((Vector6() << 1.4, 0, 0, 0, 0, 0).finished());
  const SimulatedSequence sequence = simulateSequence(options);
  for (const auto& frame : sequence.trueExtrinsics) {
    ASSERT_EQ(frame.size(), 2u);
    EXPECT_NEAR(frame[1][0], 1.4, 1e-3);
    EXPECT_NE(frame[0].tail<5>(), frame[1].tail<5>());
  }
  int third = 0;
  for (const FrameObservations& frame : sequence.frames)
    for (const Observation& o : frame.observations) third += o.camera == 2 ? 1 : 0;
  EXPECT_GT(third, 1000);
}

TEST(SimFeatures, BadOptionsThrow) {
  const auto throws = [](auto edit) {
    FeatureSimulationOptions options = shortFlight();
    edit(options);
    EXPECT_THROW(simulateSequence(options), Error);
  };
  throws([](FeatureSimulationOptions& o) { o.pixelNoise_px = -1.0; });
  throws([](FeatureSimulationOptions& o) { o.outlierFraction = 1.5; });
  throws([](FeatureSimulationOptions& o) { o.dropProbability = -0.1; });
  throws([](FeatureSimulationOptions& o) { o.points = -5; });
  throws([](FeatureSimulationOptions& o) { o.imageMargin_px = 500.0; });
  throws([](FeatureSimulationOptions& o) { o.rig.extrinsics.clear(); });
  throws([](FeatureSimulationOptions& o) { o.flight.speed_m_s = 0.0; });
  // Descending 150 m from 20 m flies into the ground.
  throws([](FeatureSimulationOptions& o) {
    o.flight.altitude_m = 20.0;
    o.flight.legs = {{FlightLeg::Kind::Climb, 200.0, 0.0, -15.0}};
  });
  const SimulatedSequence sequence = simulateSequence(shortFlight());
  EXPECT_THROW(trueCameraPose(sequence, 11, 0), Error);
  EXPECT_THROW(trueCameraPose(sequence, 0, 2), Error);
}

}  // namespace
}  // namespace lrsvo
