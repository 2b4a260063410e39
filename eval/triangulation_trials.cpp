#include "lrsvo/eval/triangulation_trials.h"

#include <random>

#include "lrsvo/graph/error.h"

namespace lrsvo {

TriangulationTrials runTriangulationTrials(const LineRig& rig, const Eigen::Vector3d& point, double noise_px,
                                           long trials, std::uint64_t seed, std::uint64_t stream) {
  if (trials < 0 || !(noise_px >= 0.0)) throw Error("triangulation trials: needs a non-negative trial count and noise");
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32)};
  std::mt19937_64 random(sequence);
  std::normal_distribution<double> noise(0.0, noise_px);

  std::vector<Eigen::Vector2d> truth, pixels(rig.cameraCount());
  for (int k = 0; k < rig.cameraCount(); ++k) truth.push_back(rig.project(k, point));

  TriangulationTrials result;
  result.depths_m.reserve(trials);
  result.errors_m.reserve(trials);
  for (long trial = 0; trial < trials; ++trial) {
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const double du = noise(random);  // two statements: the order of the draws is fixed
      const double dv = noise(random);
      pixels[k] = truth[k] + Eigen::Vector2d(du, dv);
    }
    const std::optional<Eigen::Vector3d> estimate = triangulateOnLine(rig, pixels);
    if (!estimate) {
      ++result.failed;
      continue;
    }
    result.depths_m.push_back(estimate->z());
    result.errors_m.push_back((*estimate - point).norm());
  }
  return result;
}

}  // namespace lrsvo
