// The odometry's start on rendered flights over a batch of worlds: the
// full-size camera at 30 m and 15 Hz (close range: a secondary image misses
// by tens of pixels at the long-range batch's start scale) and at 100 m and
// 10 Hz (long range: the planar twin fits the secondary images as well as the
// true motion once kappa may grow without bound). In every world the start
// takes its first samples: frame 0 is posed and no frame is given up to a
// failed attempt.
//
// The extrinsic bound. The secondary camera's pitch trades off against the
// scale: a scale error e moves the disparity d by e d, which a pitch of
// e d / f takes up. The start's scale has a relative std of about 5 % at
// 100 m and 1-3 % at 30 m on these images (its own marginal), so its pitch
// is within e d / f = 0.05 x 11.7 px / 1667 px = 0.35 mrad (100 m) and
// 0.03 x 39 px / 1667 px = 0.7 mrad (30 m) per std: 2 mrad is three stds at
// either height, a fifth of the +-10 mrad box.
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/sim/scenario.h"
#include "lrsvo/sim/sim_frame_source.h"

namespace lrsvo {
namespace {

constexpr double kMaxPitchError_rad = 2e-3;

// The demo's world, flight and flexing rig at the given height and rate,
// with every seed of the scenario set to `seed` (another world).
SimScenario startFlight(double altitude_m, double frameRate_hz, std::uint64_t seed) {
  SimScenario scenario = demoScenario();
  scenario.flight.altitude_m = altitude_m;
  scenario.flight.frameRate_hz = frameRate_hz;
  scenario.seed = scenario.flight.seed = scenario.terrain.seed = scenario.deformation.seed = scenario.texture.seed =
      seed;
  return scenario;
}

// The first frame is posed, and its note says how the segment started.
void expectStartAtFirstFrame(double altitude_m, double frameRate_hz, int frames) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(testing::Message() << altitude_m << " m, " << frameRate_hz << " Hz, seed " << seed);
    SimFrameSource source(startFlight(altitude_m, frameRate_hz, seed));
    RunOptions options;
    options.maxFrames = frames;
    std::map<int, FrameEstimate> estimates;
    options.onFrame = [&](const FrameEstimate& estimate) { estimates[estimate.frame] = estimate; };
    const RunResult run = runOdometry(source, options);
    EXPECT_EQ(run.totals.tracked, frames);
    ASSERT_TRUE(estimates.count(0));
    EXPECT_TRUE(estimates[0].tracked) << estimates[0].note;
    const std::string& note = estimates[0].note;
    EXPECT_TRUE(note.rfind("stereo start at ", 0) == 0 || note.rfind("long-range start over ", 0) == 0) << note;
    ASSERT_FALSE(estimates[0].extrinsics.empty());
    const double truePitch = source.groundTruth().extrinsics.at(0).at(0)[4];
    EXPECT_NEAR(estimates[0].extrinsics[0][4], truePitch, kMaxPitchError_rad);
  }
}

TEST(OdometryRunSim, StartsAtTheFirstFrameAtCloseRangeInEveryWorld) { expectStartAtFirstFrame(30.0, 15.0, 24); }

TEST(OdometryRunSim, StartsAtTheFirstFrameAtLongRangeInEveryWorld) { expectStartAtFirstFrame(100.0, 10.0, 14); }

}  // namespace
}  // namespace lrsvo
