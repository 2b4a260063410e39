#include "lrsvo/sim/rig_deformation.h"

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

constexpr std::uint64_t kDriftStream = 0x6472696674;            // "drift"
constexpr std::uint64_t kVibrationStream = 0x7669627261746500;  // "vibrate"

void check(bool condition, const std::string& message) {
  if (!condition) throw Error("rig deformation: " + message);
}

void validate(const Vector6& calibration, const std::vector<double>& times, const DeformationOptions& o, int camera) {
  check(camera >= 1, "camera must be a secondary camera (>= 1), got " + std::to_string(camera));
  check(calibration.allFinite(), "calibration must be finite");
  check(o.drift.allFinite() && (o.drift.array() >= 0.0).all(), "drift amplitudes must be finite and >= 0");
  check(o.vibration.allFinite() && (o.vibration.array() >= 0.0).all(), "vibration sigmas must be finite and >= 0");
  check(o.offset.allFinite(), "offset must be finite");
  check(std::isfinite(o.driftPeriod_s) && o.driftPeriod_s > 0.0, "driftPeriod_s must be finite and > 0");
  for (double t : times) check(std::isfinite(t), "times must be finite");
}

// Per parameter, three sinusoids with periods of half to twice the drift
// period, random phases and weights summing to one.
class Drift {
 public:
  Drift(const DeformationOptions& o, std::uint64_t seed) : amplitude_(o.drift) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (auto& parameter : terms_) {
      double weightSum = 0.0;
      for (Term& term : parameter) {
        const double period = o.driftPeriod_s * std::exp2(2.0 * unit(rng) - 1.0);
        term = {2.0 * std::numbers::pi / period, 2.0 * std::numbers::pi * unit(rng), unit(rng)};
        weightSum += term.weight;
      }
      for (Term& term : parameter) term.weight /= weightSum;
    }
  }

  Vector6 at(double t) const {
    Vector6 drift = Vector6::Zero();
    for (int p = 0; p < 6; ++p)
      for (const Term& term : terms_[p]) drift[p] += term.weight * std::sin(term.frequency * t + term.phase);
    return amplitude_.cwiseProduct(drift);
  }

 private:
  struct Term {
    double frequency;  // rad/s
    double phase;
    double weight;
  };
  Vector6 amplitude_;
  std::array<std::array<Term, 3>, 6> terms_{};
};

}  // namespace

std::vector<Vector6> simulateDeformation(const Vector6& calibration, const std::vector<double>& times_s,
                                         const DeformationOptions& options, int camera) {
  validate(calibration, times_s, options, camera);
  const auto cameraLabel = static_cast<std::uint64_t>(camera);
  const Drift drift(options, mixSeed(options.seed, kDriftStream, cameraLabel));
  std::mt19937_64 rng(mixSeed(options.seed, kVibrationStream, cameraLabel));
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vector6> extrinsics;
  extrinsics.reserve(times_s.size());
  for (double t : times_s) {
    Vector6 vibration;
    for (int p = 0; p < 6; ++p) vibration[p] = options.vibration[p] * normal(rng);
    extrinsics.push_back(calibration + options.offset + drift.at(t) + vibration);
  }
  return extrinsics;
}

}  // namespace lrsvo
