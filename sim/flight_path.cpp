#include "lrsvo/sim/flight_path.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

constexpr double kMaxStep_s = 1.0 / 300.0;

void check(bool condition, const std::string& message) {
  if (!condition) throw Error("flight: " + message);
}

void validateLeg(const FlightLeg& leg, double speed, std::size_t index) {
  const std::string name = "leg " + std::to_string(index) + ": ";
  check(std::isfinite(leg.length_m) && leg.length_m > 0.0, name + "length_m must be finite and > 0");
  check(std::isfinite(leg.turnRate_rad_s) && std::isfinite(leg.climbRate_m_s), name + "rates must be finite");
  switch (leg.kind) {
    case FlightLeg::Kind::Straight:
      check(leg.turnRate_rad_s == 0.0 && leg.climbRate_m_s == 0.0, name + "a straight leg takes no turn or climb rate");
      break;
    case FlightLeg::Kind::Turn:
      check(leg.turnRate_rad_s != 0.0 && leg.climbRate_m_s == 0.0,
            name + "a turn needs a non-zero turnRate_rad_s and no climb rate");
      break;
    case FlightLeg::Kind::Climb:
      check(leg.climbRate_m_s != 0.0 && std::abs(leg.climbRate_m_s) < speed && leg.turnRate_rad_s == 0.0,
            name + "a climb needs 0 < |climbRate_m_s| < speed_m_s and no turn rate");
      break;
  }
}

void validate(const FlightOptions& o) {
  check(std::isfinite(o.altitude_m) && o.altitude_m > 0.0, "altitude_m must be finite and > 0");
  check(std::isfinite(o.speed_m_s) && o.speed_m_s > 0.0, "speed_m_s must be finite and > 0");
  check(std::isfinite(o.transition_s) && o.transition_s >= 0.0, "transition_s must be finite and >= 0");
  check(!o.legs.empty(), "needs at least one leg");
  for (std::size_t i = 0; i < o.legs.size(); ++i) validateLeg(o.legs[i], o.speed_m_s, i);
}

// The share of a leg's full rate at time t into it: a trapezoid rising over
// `ramp`, flat, falling over `ramp` to the leg's end.
double rateShare(double t, double duration, double ramp) {
  if (ramp <= 0.0) return 1.0;
  return std::clamp(std::min(t, duration - t) / ramp, 0.0, 1.0);
}

// The integral of rateShare from 0 to t.
double rateShareIntegral(double t, double duration, double ramp) {
  t = std::clamp(t, 0.0, duration);
  if (ramp <= 0.0) return t;
  const double rising = std::min(t, ramp);
  double integral = rising * rising / (2.0 * ramp);
  if (t > ramp) integral += std::min(t, duration - ramp) - ramp;
  if (t > duration - ramp) {
    const double falling = t - (duration - ramp);
    integral += falling - falling * falling / (2.0 * ramp);
  }
  return integral;
}

}  // namespace

FlightPath::FlightPath(const FlightOptions& options) : speed_(options.speed_m_s) {
  validate(options);
  double start = 0.0, heading = 0.0, height = options.altitude_m;
  for (const FlightLeg& leg : options.legs) {
    const double duration = leg.length_m / speed_;
    const double ramp = leg.kind == FlightLeg::Kind::Straight ? 0.0 : std::min(options.transition_s, 0.5 * duration);
    legs_.push_back({leg, start, duration, ramp, heading, height});
    breakpoints_.insert(breakpoints_.end(), {start, start + ramp, start + duration - ramp});
    const double full = rateShareIntegral(duration, duration, ramp);
    heading += leg.turnRate_rad_s * full;
    height += leg.climbRate_m_s * full;
    start += duration;
  }
  breakpoints_.push_back(start);
  std::sort(breakpoints_.begin(), breakpoints_.end());
}

const FlightPath::Leg& FlightPath::legAt(double t) const {
  const auto after =
      std::upper_bound(legs_.begin(), legs_.end(), t, [](double time, const Leg& leg) { return time < leg.start; });
  return after == legs_.begin() ? legs_.front() : *std::prev(after);
}

PathState FlightPath::stateOn(const Leg& l, double t) const {
  const double into = std::clamp(t - l.start, 0.0, l.duration);
  const double share = rateShare(into, l.duration, l.ramp), integral = rateShareIntegral(into, l.duration, l.ramp);
  PathState s;
  s.heading = l.startHeading + l.leg.turnRate_rad_s * integral;
  s.position.z() = l.startHeight + l.leg.climbRate_m_s * integral;
  s.pathAngle = std::asin(l.leg.climbRate_m_s * share / speed_);
  // A coordinated turn banks by atan(v w / g), into the turn: a left turn (w > 0) puts the right wing up.
  s.bank = -std::atan(speed_ * l.leg.turnRate_rad_s * share / kGravity_m_s2);
  return s;
}

Eigen::Vector2d FlightPath::horizontalVelocity(const Leg& l, double t) const {
  const PathState s = stateOn(l, t);
  return speed_ * std::cos(s.pathAngle) * Eigen::Vector2d(std::cos(s.heading), std::sin(s.heading));
}

Eigen::Vector2d FlightPath::displacement(double t0, double t1) const {
  const int steps = std::max(1, static_cast<int>(std::ceil((t1 - t0) / kMaxStep_s)));
  const double h = (t1 - t0) / steps;
  const Leg& l = legAt(0.5 * (t0 + t1));  // at a leg's end, the rates may jump to the next leg's
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i < steps; ++i) {
    const double a = t0 + i * h;
    sum += horizontalVelocity(l, a) + 4.0 * horizontalVelocity(l, a + 0.5 * h) + horizontalVelocity(l, a + h);
  }
  return sum * (h / 6.0);
}

PathState FlightPath::advanceTo(double t) {
  t = std::clamp(t, 0.0, duration());
  check(t >= time_, "states must be asked for in time order");
  // Integrate piece by piece between the kinks of the rate profiles.
  for (auto kink = std::upper_bound(breakpoints_.begin(), breakpoints_.end(), time_);
       kink != breakpoints_.end() && *kink < t; ++kink) {
    horizontal_ += displacement(time_, *kink);
    time_ = *kink;
  }
  if (t > time_) horizontal_ += displacement(time_, t);
  time_ = t;
  PathState s = stateOn(legAt(t), t);
  s.position.head<2>() = horizontal_;
  return s;
}

}  // namespace lrsvo
