#include "sim/flight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "graph/error.h"
#include "sim/seed_mix.h"

namespace lrsvo {
namespace {

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
  check(std::isfinite(o.frameRate_hz) && o.frameRate_hz > 0.0, "frameRate_hz must be finite and > 0");
  check(o.frameStep >= 1, "frameStep must be >= 1");
  check(!o.legs.empty(), "needs at least one leg");
  check(std::isfinite(o.attitudeNoise_rad) && o.attitudeNoise_rad >= 0.0, "attitudeNoise_rad must be >= 0");
  for (std::size_t i = 0; i < o.legs.size(); ++i) validateLeg(o.legs[i], o.speed_m_s, i);
}

// Where the aircraft is along its path: position, heading (from world x,
// counter-clockwise), flight-path angle (nose up > 0) and bank (right wing down > 0).
struct PathState {
  Eigen::Vector3d position;
  double heading = 0.0;
  double pathAngle = 0.0;
  double bank = 0.0;
};

// The state `t` seconds into a leg that starts at `start` (level, start's heading and position).
PathState alongLeg(const FlightLeg& leg, const PathState& start, double speed, double t) {
  PathState s = start;
  s.pathAngle = 0.0;
  s.bank = 0.0;
  const Eigen::Vector3d direction(std::cos(start.heading), std::sin(start.heading), 0.0);
  switch (leg.kind) {
    case FlightLeg::Kind::Straight: s.position += speed * t * direction; break;
    case FlightLeg::Kind::Turn: {
      // Circular arc of radius speed / rate; a left turn banks left wing down.
      const double rate = leg.turnRate_rad_s;
      s.heading = start.heading + rate * t;
      s.position += (speed / rate) * Eigen::Vector3d(std::sin(s.heading) - std::sin(start.heading),
                                                     std::cos(start.heading) - std::cos(s.heading), 0.0);
      s.bank = -std::atan(speed * rate / kGravity_m_s2);
      break;
    }
    case FlightLeg::Kind::Climb: {
      const double horizontal = std::sqrt(speed * speed - leg.climbRate_m_s * leg.climbRate_m_s);
      s.position += horizontal * t * direction + Eigen::Vector3d(0.0, 0.0, leg.climbRate_m_s * t);
      s.pathAngle = std::asin(leg.climbRate_m_s / speed);
      break;
    }
  }
  return s;
}

// A smooth bounded wobble per axis (roll, pitch, yaw): three sinusoids of
// 2-10 s period with random phases and weights summing to one.
class AttitudeWobble {
 public:
  AttitudeWobble(double amplitude, std::uint64_t seed) : amplitude_(amplitude) {
    std::mt19937_64 rng(mixSeed(seed, kStream));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (auto& axis : terms_) {
      double weightSum = 0.0;
      for (Term& term : axis) {
        term = {2.0 * std::numbers::pi / (2.0 + 8.0 * unit(rng)), 2.0 * std::numbers::pi * unit(rng), unit(rng)};
        weightSum += term.weight;
      }
      for (Term& term : axis) term.weight /= weightSum;
    }
  }

  Eigen::Vector3d at(double t) const {
    Eigen::Vector3d angles = Eigen::Vector3d::Zero();
    for (int a = 0; a < 3; ++a)
      for (const Term& term : terms_[a]) angles[a] += term.weight * std::sin(term.frequency * t + term.phase);
    return amplitude_ * angles;
  }

 private:
  static constexpr std::uint64_t kStream = 0x776f62626c65;  // "wobble"
  struct Term {
    double frequency;  // rad/s
    double phase;
    double weight;
  };
  double amplitude_;
  std::array<std::array<Term, 3>, 3> terms_{};
};

// Base camera pose from the path state and the wobble (roll, pitch, yaw).
// Body axes: x forward, y left, z up; world-from-body = Rz(heading) Ry(-pitch)
// Rx(bank). The camera's axes in the body: x forward, y right, z down.
Eigen::Isometry3d cameraFromWorld(const PathState& s, const Eigen::Vector3d& wobble) {
  const Eigen::Matrix3d worldFromBody = (Eigen::AngleAxisd(s.heading + wobble.z(), Eigen::Vector3d::UnitZ()) *
                                         Eigen::AngleAxisd(-(s.pathAngle + wobble.y()), Eigen::Vector3d::UnitY()) *
                                         Eigen::AngleAxisd(s.bank + wobble.x(), Eigen::Vector3d::UnitX()))
                                            .toRotationMatrix();
  const Eigen::Matrix3d worldFromCamera = worldFromBody * Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = worldFromCamera.transpose();
  pose.translation() = -pose.linear() * s.position;
  return pose;
}

}  // namespace

std::vector<FlightPose> simulateFlight(const FlightOptions& options) {
  validate(options);
  const AttitudeWobble wobble(options.attitudeNoise_rad, options.seed);
  // Leg start times and states.
  std::vector<double> legStart{0.0};
  std::vector<PathState> legState{{Eigen::Vector3d(0.0, 0.0, options.altitude_m)}};
  for (const FlightLeg& leg : options.legs) {
    const double duration = leg.length_m / options.speed_m_s;
    legState.push_back(alongLeg(leg, legState.back(), options.speed_m_s, duration));
    legStart.push_back(legStart.back() + duration);
  }
  const double end = legStart.back();
  // The tolerance keeps the last frame of a flight lasting a whole number of frame periods.
  const auto lastFrame = static_cast<long>(std::floor(end * options.frameRate_hz + 1e-9));
  std::vector<FlightPose> poses;
  std::size_t leg = 0;
  for (long frame = 0; frame <= lastFrame; frame += options.frameStep) {
    const double t = static_cast<double>(frame) / options.frameRate_hz;
    while (leg + 1 < options.legs.size() && t >= legStart[leg + 1]) ++leg;
    const double intoLeg = std::min(t, end) - legStart[leg];
    const PathState state = alongLeg(options.legs[leg], legState[leg], options.speed_m_s, intoLeg);
    poses.push_back({t, cameraFromWorld(state, wobble.at(t))});
  }
  return poses;
}

}  // namespace lrsvo
