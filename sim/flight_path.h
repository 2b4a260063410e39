#pragma once

#include <vector>

#include <Eigen/Core>

#include "lrsvo/sim/flight.h"

namespace lrsvo {

// The aircraft on its path at one time: position (world, z up), heading (from
// world x, counter-clockwise), flight-path angle (nose up > 0) and bank
// (right wing down > 0).
struct PathState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double heading = 0.0;
  double pathAngle = 0.0;
  double bank = 0.0;
};

// The path through a flight's legs, flown at constant speed from (0, 0,
// altitude) heading along world x. Heading, height, pitch and bank have closed
// forms; the horizontal position is integrated (Simpson's rule on steps of at
// most 1/300 s, exact to far below a micrometre), so states are asked for in
// time order.
class FlightPath {
 public:
  // Throws lrsvo::Error on a non-positive altitude or speed, a negative
  // transition, no legs, or a leg that does not fit its kind.
  explicit FlightPath(const FlightOptions& options);

  double duration() const { return legs_.back().start + legs_.back().duration; }
  // The state at time t (clamped to [0, duration]); t must not decrease from call to call.
  PathState advanceTo(double t);

 private:
  struct Leg {
    FlightLeg leg;
    double start;     // s
    double duration;  // s
    double ramp;      // s, at each end
    double startHeading;
    double startHeight;
  };
  const Leg& legAt(double t) const;
  // All but the horizontal position, at time t flown on leg l.
  PathState stateOn(const Leg& l, double t) const;
  Eigen::Vector2d horizontalVelocity(const Leg& l, double t) const;
  // Simpson's rule for the horizontal displacement over [t0, t1], inside one smooth piece of one leg.
  Eigen::Vector2d displacement(double t0, double t1) const;

  double speed_;
  std::vector<Leg> legs_;
  std::vector<double> breakpoints_;  // leg starts and ramp ends, where the rates have kinks
  double time_ = 0.0;
  Eigen::Vector2d horizontal_ = Eigen::Vector2d::Zero();
};

}  // namespace lrsvo
