#include "lrsvo/sim/flight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/sim/flight_path.h"

namespace lrsvo {
namespace {

void check(bool condition, const std::string& message) {
  if (!condition) throw Error("flight: " + message);
}

void validate(const FlightOptions& o) {
  check(std::isfinite(o.frameRate_hz) && o.frameRate_hz > 0.0, "frameRate_hz must be finite and > 0");
  check(o.frameStep >= 1, "frameStep must be >= 1");
  check(std::isfinite(o.attitudeNoise_rad) && o.attitudeNoise_rad >= 0.0, "attitudeNoise_rad must be >= 0");
  for (const AttitudeStep& gust : o.gusts)
    check(std::isfinite(gust.time_s) && gust.size_rad.allFinite() && gust.rise_s >= 0.0 && gust.hold_s >= 0.0 &&
              std::isfinite(gust.rise_s + gust.hold_s),
          "a gust needs a finite time and size, and finite rise_s and hold_s >= 0");
}

Eigen::Vector3d gustOffset(const std::vector<AttitudeStep>& gusts, double t) {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (const AttitudeStep& gust : gusts) offset += gust.weightAt(t) * gust.size_rad;
  return offset;
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

double AttitudeStep::weightAt(double t) const {
  const double since = t - time_s, untilEnd = time_s + 2.0 * rise_s + hold_s - t;
  if (since <= 0.0 || untilEnd <= 0.0) return 0.0;
  if (rise_s == 0.0) return 1.0;
  return std::min({1.0, since / rise_s, untilEnd / rise_s});
}

std::vector<FlightPose> simulateFlight(const FlightOptions& options) {
  validate(options);
  FlightPath path(options);
  const AttitudeWobble wobble(options.attitudeNoise_rad, options.seed);
  // The tolerance keeps the last frame of a flight lasting a whole number of frame periods.
  const auto lastFrame = static_cast<long>(std::floor(path.duration() * options.frameRate_hz + 1e-9));
  std::vector<FlightPose> poses;
  for (long frame = 0; frame <= lastFrame; frame += options.frameStep) {
    const double t = static_cast<double>(frame) / options.frameRate_hz;
    poses.push_back({t, cameraFromWorld(path.advanceTo(t), wobble.at(t) + gustOffset(options.gusts, t))});
  }
  return poses;
}

}  // namespace lrsvo
