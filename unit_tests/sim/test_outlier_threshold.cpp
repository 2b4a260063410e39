// The window's outlier test: a threshold that follows the errors' own noise,
// and what it catches that a fixed 4 px threshold lets through.

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/outlier_threshold.h"
#include "lrsvo/frontend/odometry/sliding_window.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/sim/feature_simulator.h"

namespace lrsvo {
namespace {

// Lengths of seeded 2-D Gaussian errors of sigma per axis.
std::vector<double> gaussianErrorLengths(int count, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> lengths;
  for (int i = 0; i < count; ++i) lengths.push_back(std::hypot(normal(rng), normal(rng)));
  return lengths;
}

TEST(OutlierThreshold, NoiseEstimateRecoversSigmaAndShrugsOffAMinority) {
  for (double sigma : {0.05, 0.3, 2.0}) {
    std::vector<double> errors = gaussianErrorLengths(4000, sigma, 7);
    EXPECT_NEAR(robustNoiseSigma_px(errors), sigma, 0.05 * sigma);
    // 15 % gross errors move the median to Rayleigh's 59th percentile: 13 % up.
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> gross(10.0 * sigma, 100.0 * sigma);
    for (int i = 0; i < 700; ++i) errors.push_back(gross(rng));
    EXPECT_NEAR(robustNoiseSigma_px(errors), 1.13 * sigma, 0.06 * sigma);
  }
  EXPECT_EQ(robustNoiseSigma_px({}), 0.0);
}

TEST(OutlierThreshold, IsSigmasTimesTheNoiseWithinItsBounds) {
  const OutlierTestOptions options;  // 4 sigma within [0.5, 4] px
  const std::vector<double> errors = gaussianErrorLengths(4000, 0.3, 9);
  EXPECT_NEAR(outlierThreshold_px(errors, options), 4.0 * robustNoiseSigma_px(errors), 1e-12);
  EXPECT_EQ(outlierThreshold_px(gaussianErrorLengths(100, 0.01, 9), options), 0.5);
  EXPECT_EQ(outlierThreshold_px(gaussianErrorLengths(100, 5.0, 9), options), 4.0);
  EXPECT_EQ(outlierThreshold_px({}, options), 4.0);
  EXPECT_EQ(outlierThreshold_px(errors, {.sigmas = 0.0}), 4.0);
  EXPECT_THROW(outlierThreshold_px(errors, {.sigmas = -1.0}), Error);
  EXPECT_THROW(outlierThreshold_px(errors, {.minThreshold_px = 0.0}), Error);
  EXPECT_THROW(outlierThreshold_px(errors, {.minThreshold_px = 5.0, .maxThreshold_px = 4.0}), Error);
  EXPECT_THROW(outlierThreshold_px(errors, {.sigmas = std::nan("")}), Error);
  EXPECT_THROW(outlierThreshold_px(errors, {.minImageErrors = 0}), Error);
}

// Tracks whose base-camera pixels slide steadily across the ground, each its
// own way, like corners where a tree crown's outline crosses the ground
// behind it: no fixed point explains them, yet each keyframe moves them by a
// fraction of a pixel (0.15 px: about 2 px over a 15-keyframe window).
struct SlidingTracks {
  SimulatedSequence sequence;
  std::set<int> sliding;
};

// A 60 m straight flight at 80 m over treeless ground, 300 points a frame.
SimulatedSequence straightFlight(std::uint64_t seed) {
  FeatureSimulationOptions options;
  options.flight.altitude_m = 80.0;
  options.flight.speed_m_s = 20.0;
  options.flight.legs = {{FlightLeg::Kind::Straight, 60.0}};
  options.terrain.treeDensity_per_km2 = 0.0;
  options.pointsPerFrame = 300;
  options.pixelNoise_px = 0.15;  // KLT on sharp texture
  options.seed = seed;
  return simulateSequence(options);
}

SlidingTracks flightWithSlidingTracks() {
  SlidingTracks result{straightFlight(11), {}};
  std::map<int, Eigen::Vector2d> slide;  // px per frame
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  for (int track = 0; track < static_cast<int>(result.sequence.truePoints.size()); track += 12) {
    const double a = angle(rng);
    slide[track] = 0.05 * Eigen::Vector2d(std::cos(a), std::sin(a));
    result.sliding.insert(track);
  }
  for (std::size_t frame = 0; frame < result.sequence.frames.size(); ++frame)
    for (Observation& o : result.sequence.frames[frame].observations)
      if (o.camera == 0 && result.sliding.count(o.track)) o.pixel += static_cast<double>(frame) * slide[o.track];
  return result;
}

// The tracks the window rejects along the flight, a keyframe every 3 frames.
std::set<int> rejectedAlongTheFlight(const SimulatedSequence& sequence, const OutlierTestOptions& outliers) {
  OdometryOptions options;
  options.outliers = outliers;
  SlidingWindow window(sequence.rig, options);
  std::vector<Keyframe> keyframes;
  for (int i = 0; i < 5; ++i) keyframes.push_back({3 * i, sequence.trueCameraFromWorld[3 * i], sequence.frames[3 * i]});
  window.reset(keyframes, {}, sequence.trueExtrinsics[12], 0.02);
  std::set<int> rejected;
  for (int frame = 15; frame < static_cast<int>(sequence.frames.size()); frame += 3) {
    // Started where the true motion since the last keyframe takes the window's own pose of it, as a pose
    // estimate on the window's map would.
    const Keyframe& last = window.keyframes().back();
    const Eigen::Isometry3d motion =
        sequence.trueCameraFromWorld[frame] * sequence.trueCameraFromWorld[last.frame].inverse();
    window.addKeyframe({frame, motion * last.cameraFromWorld, sequence.frames[frame]});
    window.triangulateNewTracks();
    const WindowAdjustment adjustment = window.adjust();
    rejected.insert(adjustment.rejectedTracks.begin(), adjustment.rejectedTracks.end());
    window.retire();
  }
  return rejected;
}

TEST(OutlierThreshold, WindowRejectsSlidingTracksThatFourPixelsKeep) {
  const SlidingTracks flight = flightWithSlidingTracks();
  int slidingSeen = 0, goodSeen = 0;
  std::set<int> seen;
  for (const FrameObservations& frame : flight.sequence.frames)
    for (const Observation& o : frame.observations) seen.insert(o.track);
  for (int track : seen) (flight.sliding.count(track) ? slidingSeen : goodSeen)++;
  ASSERT_GT(slidingSeen, 20);

  auto count = [&](const std::set<int>& rejected, bool sliding) {
    int n = 0;
    for (int track : rejected) n += flight.sliding.count(track) == static_cast<std::size_t>(sliding);
    return n;
  };
  const std::set<int> adaptive = rejectedAlongTheFlight(flight.sequence, {});
  const std::set<int> fixed = rejectedAlongTheFlight(flight.sequence, {.sigmas = 0.0});
  std::printf("sliding tracks rejected: %d of %d adaptive, %d fixed; good ones: %d and %d of %d\n",
              count(adaptive, true), slidingSeen, count(fixed, true), count(adaptive, false), count(fixed, false),
              goodSeen);
  EXPECT_GE(count(adaptive, true), slidingSeen / 2);
  EXPECT_LE(count(fixed, true), slidingSeen / 10);
  // 4 sigma keeps the good tracks but a few: each observation is tested at every keyframe of its track's
  // life (a 15-view track passes a Gaussian 4 sigma test with probability (1 - e^-8)^15, 99.5 %), and a
  // short track's residuals, fitted by its own point, understate the noise.
  EXPECT_LE(count(adaptive, false), goodSeen / 20);
}

// A jolt of the rig at one keyframe: its secondary camera's pixels are all
// 4 px off in y, more than the one S the window shares can follow. That
// keyframe's pose splits the miss between its two cameras, so its base
// observations are off together, most of them past the window's threshold:
// held to that threshold alone (minImageErrors past any image's count), the
// keyframe would lose most of its tracks. Off as a whole, it loses its stereo
// observations, and most of its tracks stay.
TEST(OutlierThreshold, AKeyframeWhoseStereoPairTheWindowsSMissesKeepsItsTracks) {
  for (const std::uint64_t seed : {11u, 21u, 31u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    SimulatedSequence sequence = straightFlight(seed);
    constexpr int kJoltedFrame = 30;  // a keyframe: rejectedAlongTheFlight takes every third frame
    constexpr double kJolt_px = 4.0;
    std::set<int> joltedTracks;
    for (Observation& o : sequence.frames[kJoltedFrame].observations) {
      if (o.camera == 1) o.pixel.y() += kJolt_px;
      if (o.camera == 0) joltedTracks.insert(o.track);
    }
    auto condemnedOfJolted = [&](const std::set<int>& rejected) {
      int n = 0;
      for (int track : rejected) n += static_cast<int>(joltedTracks.count(track));
      return n;
    };
    const int offAsAWhole = condemnedOfJolted(rejectedAlongTheFlight(sequence, {}));
    const int windowOnly = condemnedOfJolted(rejectedAlongTheFlight(sequence, {.minImageErrors = 1 << 30}));
    std::printf("seed %d: tracks of the jolted keyframe condemned: %d of %zu, %d by the window's threshold alone\n",
                static_cast<int>(seed), offAsAWhole, joltedTracks.size(), windowOnly);
    ASSERT_GT(joltedTracks.size(), 100u);
    const double half = 0.5 * static_cast<double>(joltedTracks.size());
    EXPECT_GT(windowOnly, half);
    EXPECT_LT(offAsAWhole, half);
  }
}

}  // namespace
}  // namespace lrsvo
