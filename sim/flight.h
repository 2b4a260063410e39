#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

namespace lrsvo {

// One leg of a flight at constant speed. Straight: level, constant heading.
// Turn: level, heading changing at turnRate_rad_s (> 0: to the left, counter-
// clockwise seen from above), banked as a coordinated turn. Climb: straight,
// height changing at climbRate_m_s (< 0: descent), nose up along the path.
// length_m is the distance flown along the path. Rates ramp in and out over
// FlightOptions::transition_s.
struct FlightLeg {
  enum class Kind { Straight, Turn, Climb };
  Kind kind = Kind::Straight;
  double length_m = 0.0;
  double turnRate_rad_s = 0.0;  // Turn only
  double climbRate_m_s = 0.0;   // Climb only
};

// A gust: the attitude steps by size_rad (roll, pitch, yaw) over rise_s from
// time_s on, holds the step for hold_s, and returns as fast. A roll of
// 12.75 deg within 0.1 s moves a nadir image by about f tan(12.75 deg): 380 px
// at the paper's f = 1668 px.
struct AttitudeStep {
  double time_s = 0.0;
  Eigen::Vector3d size_rad = Eigen::Vector3d::Zero();
  double rise_s = 0.1;
  double hold_s = 1.0;
  // The step's share of size_rad at time t: 0 before and after it, 1 while held.
  double weightAt(double t) const;
};

// World z up; the aircraft starts at (0, 0, altitude_m) heading along world
// x and flies along its body x with the cameras looking down.
struct FlightOptions {
  double altitude_m = 100.0;   // above the terrain's mean height (z = 0) at the start
  double speed_m_s = 20.0;     // along the path
  double frameRate_hz = 30.0;  // camera frames per second
  int frameStep = 1;           // keep every frameStep-th frame (the paper's init: one every 3 frames)
  std::vector<FlightLeg> legs = {{FlightLeg::Kind::Straight, 60.0}};
  // Amplitude of a smooth seeded roll, pitch and yaw wobble on top of the
  // path's attitude (a few sinusoids of 2-10 s period per axis); 0: none.
  double attitudeNoise_rad = 0.0;
  // Attitude steps on top of the wobble (their offsets add up).
  std::vector<AttitudeStep> gusts;
  // Turns and climbs ramp their rate (and so bank and pitch) linearly in and
  // out over this time at each end of the leg, as an aircraft rolls into a
  // turn in about a second; 0: instantly. A turn's heading change is then
  // turnRate * (duration - transition), a climb's height change likewise.
  double transition_s = 1.0;
  std::uint64_t seed = 1;
};

// Ground truth of one kept frame: its time (frame index / frame rate) and
// the pose of the BASE camera, camera-from-world. The base camera has x along
// the fuselage (flight direction), z down (nadir when level), y = z cross x.
struct FlightPose {
  double time_s = 0.0;
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
};

// Every kept frame from t = 0 to the end of the last leg. Throws lrsvo::Error
// on non-positive speed, frame rate, frame step or altitude, on no legs, and
// on a leg that does not fit its kind (e.g. a climb rate not below the speed).
// Occlusion and the terrain are not known here: sim/feature_simulator.h
// checks that the aircraft stays above the ground.
std::vector<FlightPose> simulateFlight(const FlightOptions& options);

// Standard gravity, for the bank angle of a coordinated turn: tan(bank) = v * turnRate / g.
inline constexpr double kGravity_m_s2 = 9.80665;

}  // namespace lrsvo
