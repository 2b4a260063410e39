#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/flight.h"

namespace lrsvo {
namespace {

Eigen::Vector3d centreOf(const FlightPose& pose) { return pose.cameraFromWorld.inverse().translation(); }
// Camera axis `axis` (0 x, 1 y, 2 z) expressed in the world.
Eigen::Vector3d axisOf(const FlightPose& pose, int axis) { return pose.cameraFromWorld.linear().row(axis).transpose(); }

TEST(SimFlight, StraightLegAt30MetresPerSecondKeepingEveryThirdFrameAdvances3Metres) {
  FlightOptions options;
  options.altitude_m = 80.0;
  options.speed_m_s = 30.0;
  options.frameRate_hz = 30.0;
  options.frameStep = 3;
  options.legs = {{FlightLeg::Kind::Straight, 60.0}};
  const std::vector<FlightPose> poses = simulateFlight(options);
  // 60 m at 30 m/s is 2 s: frames 0, 3, ..., 60 of 30 Hz.
  ASSERT_EQ(poses.size(), 21u);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(poses[i].time_s, 0.1 * i, 1e-12);
    EXPECT_TRUE(centreOf(poses[i]).isApprox(Eigen::Vector3d(3.0 * i, 0.0, 80.0), 1e-12)) << centreOf(poses[i]);
    EXPECT_TRUE(axisOf(poses[i], 0).isApprox(Eigen::Vector3d::UnitX(), 1e-12));   // along the flight
    EXPECT_TRUE(axisOf(poses[i], 2).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));  // looking down
    EXPECT_TRUE(axisOf(poses[i], 1).isApprox(-Eigen::Vector3d::UnitY(), 1e-12));  // z cross x
  }
  // A ground point straight below the camera, 80 m away, on the optical axis.
  const Eigen::Vector3d below = poses[5].cameraFromWorld * Eigen::Vector3d(15.0, 0.0, 0.0);
  EXPECT_TRUE(below.isApprox(Eigen::Vector3d(0.0, 0.0, 80.0), 1e-12));
}

TEST(SimFlight, TurnChangesHeadingByRateTimesTimeOnACircleWithACoordinatedBank) {
  FlightOptions options;
  options.speed_m_s = 20.0;
  options.frameRate_hz = 10.0;
  options.transition_s = 0.0;
  const double rate = 0.2;
  options.legs = {{FlightLeg::Kind::Turn, 40.0, rate}};  // 2 s: 0.4 rad to the left
  const std::vector<FlightPose> poses = simulateFlight(options);
  ASSERT_EQ(poses.size(), 21u);
  const double bank = std::atan(20.0 * rate / kGravity_m_s2);
  const Eigen::Vector3d turnCentre(0.0, 20.0 / rate, options.altitude_m);  // left of the start, radius v / rate
  for (const FlightPose& pose : poses) {
    const double heading = rate * pose.time_s;
    EXPECT_TRUE(axisOf(pose, 0).isApprox(Eigen::Vector3d(std::cos(heading), std::sin(heading), 0.0), 1e-12));
    EXPECT_NEAR((centreOf(pose) - turnCentre).norm(), 100.0, 1e-9);
    // Banked by atan(v w / g): the view tilts away from the turn's centre.
    const Eigen::Vector3d view = axisOf(pose, 2);
    EXPECT_NEAR(std::acos(-view.z()), bank, 1e-12);
    EXPECT_LT(view.dot(turnCentre - centreOf(pose)), 0.0);
  }
  EXPECT_NEAR(std::atan2(axisOf(poses.back(), 0).y(), axisOf(poses.back(), 0).x()), 0.4, 1e-12);
}

TEST(SimFlight, ClimbRisesAtItsRateWithTheNoseUpAlongThePath) {
  FlightOptions options;
  options.altitude_m = 50.0;
  options.speed_m_s = 20.0;
  options.frameRate_hz = 5.0;
  options.transition_s = 0.0;
  options.legs = {{FlightLeg::Kind::Climb, 40.0, 0.0, 2.0}};
  const std::vector<FlightPose> poses = simulateFlight(options);
  ASSERT_EQ(poses.size(), 11u);
  const Eigen::Vector3d end = centreOf(poses.back());
  EXPECT_NEAR(end.z(), 54.0, 1e-9);
  EXPECT_NEAR(end.x(), 2.0 * std::sqrt(400.0 - 4.0), 1e-9);
  EXPECT_NEAR(axisOf(poses.back(), 0).z(), 0.1, 1e-12);  // sin(path angle) = climb rate / speed
}

TEST(SimFlight, RampedTurnRollsInAndOutSmoothly) {
  FlightOptions options;
  options.speed_m_s = 20.0;
  options.frameRate_hz = 30.0;
  options.transition_s = 1.0;
  const double rate = 0.2, dt = 1.0 / 30.0;
  options.legs = {{FlightLeg::Kind::Turn, 100.0, rate}};  // 5 s, the rate ramping over the first and last second
  const std::vector<FlightPose> poses = simulateFlight(options);
  ASSERT_EQ(poses.size(), 151u);
  const auto heading = [&](std::size_t i) { return std::atan2(axisOf(poses[i], 0).y(), axisOf(poses[i], 0).x()); };
  const auto bank = [&](std::size_t i) { return std::acos(-axisOf(poses[i], 2).z()); };
  EXPECT_NEAR(heading(150), rate * (5.0 - 1.0), 1e-12);     // the trapezoid's area
  EXPECT_NEAR(heading(15), rate * 0.5 * 0.5 / 2.0, 1e-12);  // half way up the ramp: w t^2 / (2 ramp)
  EXPECT_NEAR(heading(90) - heading(60), rate * 1.0, 1e-12);
  EXPECT_NEAR(bank(0), 0.0, 1e-7);
  EXPECT_NEAR(bank(75), std::atan(20.0 * rate / kGravity_m_s2), 1e-12);
  EXPECT_NEAR(bank(150), 0.0, 1e-7);
  // bank = atan(k t) on the ramp, k = v w / (g ramp): it changes by at most k dt per frame.
  const double k = 20.0 * rate / kGravity_m_s2;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    EXPECT_LE(std::abs(bank(i) - bank(i - 1)), k * dt + 1e-12);
    // Constant speed along the path: a frame's chord is at most, and nearly, v dt.
    const double chord = (centreOf(poses[i]) - centreOf(poses[i - 1])).norm();
    EXPECT_LE(chord, 20.0 * dt + 1e-9);
    EXPECT_GT(chord, 20.0 * dt * (1.0 - 1e-4));
  }
}

TEST(SimFlight, LegsJoinContinuouslyAndEachStartsFromThePreviousHeadingAndHeight) {
  FlightOptions options;
  options.speed_m_s = 25.0;
  options.frameRate_hz = 25.0;
  options.legs = {{FlightLeg::Kind::Straight, 50.0},
                  {FlightLeg::Kind::Turn, 50.0, -0.25},
                  {FlightLeg::Kind::Climb, 50.0, 0.0, 5.0},
                  {FlightLeg::Kind::Straight, 50.0}};
  const std::vector<FlightPose> poses = simulateFlight(options);
  ASSERT_EQ(poses.size(), 201u);
  for (std::size_t i = 1; i < poses.size(); ++i)
    EXPECT_NEAR((centreOf(poses[i]) - centreOf(poses[i - 1])).norm(), 1.0, 1e-3);  // 25 m/s at 25 Hz
  // 2 s legs with 1 s ramps at each end: the turn changes the heading by
  // -0.25 rad/s * 1 s, the climb the height by 5 m/s * 1 s.
  const Eigen::Vector3d direction(std::cos(-0.25), std::sin(-0.25), 0.0);
  EXPECT_TRUE(axisOf(poses.back(), 0).isApprox(direction, 1e-12));
  const Eigen::Vector3d lastLeg = centreOf(poses[200]) - centreOf(poses[150]);
  EXPECT_TRUE(lastLeg.isApprox(50.0 * direction, 1e-9)) << lastLeg.transpose();
  EXPECT_NEAR(centreOf(poses.back()).z(), 105.0, 1e-9);
}

TEST(SimFlight, AttitudeNoiseIsBoundedSeededAndLeavesThePathAlone) {
  FlightOptions options;
  options.attitudeNoise_rad = 0.01;
  const std::vector<FlightPose> a = simulateFlight(options), b = simulateFlight(options);
  options.seed = 2;
  const std::vector<FlightPose> c = simulateFlight(options);
  double largest = 0.0;
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i].cameraFromWorld.isApprox(b[i].cameraFromWorld, 0.0));
    differs = differs || !a[i].cameraFromWorld.isApprox(c[i].cameraFromWorld, 1e-9);
    EXPECT_TRUE(centreOf(a[i]).isApprox(Eigen::Vector3d(20.0 * a[i].time_s, 0.0, 100.0), 1e-9));
    // Roll and pitch of at most 0.01 rad each tilt the view by at most ~0.0141 rad.
    const double tilt = std::acos(-axisOf(a[i], 2).z());
    EXPECT_LE(tilt, 0.01 * std::sqrt(2.0) + 1e-9);
    largest = std::max(largest, tilt);
  }
  EXPECT_GT(largest, 1e-3);
  EXPECT_TRUE(differs);
}

TEST(SimFlight, BadOptionsThrow) {
  const auto throws = [](auto edit) {
    FlightOptions options;
    edit(options);
    EXPECT_THROW(simulateFlight(options), Error);
  };
  throws([](FlightOptions& o) { o.speed_m_s = 0.0; });
  throws([](FlightOptions& o) { o.frameRate_hz = -30.0; });
  throws([](FlightOptions& o) { o.frameStep = 0; });
  throws([](FlightOptions& o) { o.altitude_m = 0.0; });
  throws([](FlightOptions& o) { o.legs.clear(); });
  throws([](FlightOptions& o) { o.legs = {{FlightLeg::Kind::Straight, 0.0}}; });
  throws([](FlightOptions& o) { o.legs = {{FlightLeg::Kind::Straight, 10.0, 0.1}}; });
  throws([](FlightOptions& o) { o.legs = {{FlightLeg::Kind::Turn, 10.0, 0.0}}; });
  throws([](FlightOptions& o) { o.legs = {{FlightLeg::Kind::Climb, 10.0, 0.0, 20.0}}; });  // as fast as the aircraft
  throws([](FlightOptions& o) { o.attitudeNoise_rad = -0.1; });
  throws([](FlightOptions& o) { o.transition_s = -1.0; });
}

}  // namespace
}  // namespace lrsvo
