// The sliding window's S with a rate: a rig that flexes within one window's
// span is followed at the newest keyframe, where one constant S lags.

#include <cmath>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/sliding_window.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/sim/feature_simulator.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

// A level flight at 60 m whose rig's angles swing by up to 8 mrad with 3-12 s
// periods (a few mrad/s): S moves by pixels within a window's ~1.5 s.
SimulatedSequence fastFlexingFlight(std::uint64_t seed) {
  FeatureSimulationOptions options;
  options.flight.altitude_m = 60.0;
  options.flight.speed_m_s = 20.0;
  options.flight.legs = {{FlightLeg::Kind::Straight, 90.0}};
  options.flight.attitudeNoise_rad = 0.01;
  options.flight.seed = seed;
  options.terrain.treeDensity_per_km2 = 0.0;
  options.pointsPerFrame = 300;
  options.pixelNoise_px = 0.5;
  options.deformation.drift << 2e-4, 2e-4, 2e-4, 8e-3, 8e-3, 8e-3;
  options.deformation.driftPeriod_s = 6.0;
  options.deformation.seed = seed;
  options.seed = seed;
  return simulateSequence(options);
}

// The RMS error of S's angles at the newest keyframe over a window sliding
// along the flight (a keyframe every 3 frames, poses started at the truth).
double newestAngleError_rad(const SimulatedSequence& sequence, const OdometryOptions& options) {
  SlidingWindow window(sequence.rig, options);
  std::vector<Keyframe> keyframes;
  for (int i = 0; i < 5; ++i) keyframes.push_back({3 * i, sequence.trueCameraFromWorld[3 * i], sequence.frames[3 * i]});
  window.reset(keyframes, {}, sequence.trueExtrinsics[12], 0.02);
  window.triangulateNewTracks();
  window.adjust();
  double sum = 0.0;
  int count = 0;
  for (int frame = 15; frame + 3 < static_cast<int>(sequence.frames.size()); frame += 3) {
    window.addKeyframe({frame, sequence.trueCameraFromWorld[frame], sequence.frames[frame]});
    window.triangulateNewTracks();
    window.adjust();
    window.retire();
    if (frame < 60) continue;  // a full window first
    const Vector6 error = window.extrinsics()[0] - sequence.trueExtrinsics[frame][0];
    sum += error.tail<3>().squaredNorm();
    count += 3;
  }
  return std::sqrt(sum / count);
}

TEST(ExtrinsicRateWindow, FollowsAFlexingRigAtTheNewestKeyframe) {
  OdometryOptions drifting;
  OdometryOptions constant;
  constant.extrinsicRateSigma = 0.0;
  double driftingError = 0.0, constantError = 0.0;
  for (std::uint64_t seed : {3, 4}) {
    const SimulatedSequence sequence = fastFlexingFlight(seed);
    driftingError += newestAngleError_rad(sequence, drifting);
    constantError += newestAngleError_rad(sequence, constant);
  }
  EXPECT_LT(driftingError, 0.7 * constantError) << "with a rate " << driftingError << ", one S " << constantError;
}

// The rate is reported, reported S moves on with it, and S between
// adjustments stays in the rig's box.
TEST(ExtrinsicRateWindow, ExtrinsicMovesOnAtItsRateInsideTheBox) {
  const SimulatedSequence sequence = fastFlexingFlight(5);
  OdometryOptions options;
  SlidingWindow window(sequence.rig, options);
  std::vector<Keyframe> keyframes;
  for (int i = 0; i < options.windowSize; ++i)
    keyframes.push_back({3 * i, sequence.trueCameraFromWorld[3 * i], sequence.frames[3 * i]});
  window.reset(keyframes, {}, sequence.trueExtrinsics[0], 0.02);
  EXPECT_TRUE(window.extrinsicRates()[0].isZero());
  window.triangulateNewTracks();
  window.adjust();
  const Vector6 rate = window.extrinsicRates()[0];
  EXPECT_GT(rate.tail<3>().norm(), 0.0);
  const double now = keyframes.back().observations.time_s;
  const Vector6 moved = window.extrinsicsAt(now + 0.1)[0] - window.extrinsics()[0];
  const Vector6 box = sequence.rig.tolerance;
  for (int i = 0; i < 6; ++i) {
    if (std::abs(window.extrinsics()[0][i] + 0.1 * rate[i] - sequence.rig.extrinsics[0][i]) < box[i]) {
      EXPECT_NEAR(moved[i], 0.1 * rate[i], 1e-12) << "parameter " << i;
    }
  }
  const Vector6 far = window.extrinsicsAt(now + 1e3)[0] - sequence.rig.extrinsics[0];
  EXPECT_TRUE((far.cwiseAbs().array() <= box.array() + 1e-15).all());
}

TEST(BundleGraphExtrinsicRate, NeedsItsExtrinsicAPositivePriorAndNoKappa) {
  const SimulatedSequence sequence = fastFlexingFlight(6);
  SparseMap map;
  map.cameraFromWorld = {sequence.trueCameraFromWorld[0]};
  const Vector6 sigma = Vector6::Constant(0.01);
  BundleGraph graph(sequence.rig, map, 1);
  EXPECT_THROW(graph.addExtrinsicRate(1, Vector6::Zero(), sigma, 0.0), Error);  // no extrinsic yet
  graph.addExtrinsic(1, sequence.rig.extrinsics[0], false);
  EXPECT_THROW(graph.addExtrinsicRate(1, Vector6::Zero(), Vector6::Zero(), 0.0), Error);
  ASSERT_NE(graph.addExtrinsicRate(1, Vector6::Zero(), sigma, 0.0), nullptr);
  EXPECT_EQ(graph.extrinsicRate(1), graph.graph().vertex(graph.extrinsicRate(1)->id()));
  EXPECT_THROW(graph.addScale(1.0), Error);
  BundleGraph scaled(sequence.rig, map, 1);
  scaled.addExtrinsic(1, sequence.rig.extrinsics[0], false);
  scaled.addScale(1.0);
  EXPECT_THROW(scaled.addExtrinsicRate(1, Vector6::Zero(), sigma, 0.0), Error);
}

}  // namespace
}  // namespace lrsvo
