#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/eval/line_rig.h"

namespace lrsvo {

// The outcome of a Monte Carlo triangulation run (the paper's Figs. 6 and 7).
struct TriangulationTrials {
  std::vector<double> depths_m;  // triangulated depth (z) of each trial that gave a point
  std::vector<double> errors_m;  // its Euclidean distance from the true point, in the same order
  long failed = 0;               // trials with no point in front of the rig (fitted disparity <= 0)

  long count() const { return static_cast<long>(depths_m.size()) + failed; }
};

// `trials` noisy sightings of `point` by every camera of `rig`: each pixel gets
// independent zero-mean Gaussian noise of `noise_px` on both axes, then the
// point is triangulated (triangulateOnLine). Draws come from a generator
// seeded by (seed, stream): one stream per case keeps cases independent of their order.
TriangulationTrials runTriangulationTrials(const LineRig& rig, const Eigen::Vector3d& point, double noise_px,
                                           long trials, std::uint64_t seed, std::uint64_t stream);

}  // namespace lrsvo
