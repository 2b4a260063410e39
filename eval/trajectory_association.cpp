#include "lrsvo/eval/trajectory_association.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "lrsvo/graph/error.h"

namespace lrsvo {

AssociatedTrajectories associateByTime(const Trajectory& estimate, const Trajectory& truth, double maxDifference_s) {
  if (!(maxDifference_s >= 0.0))
    throw Error("association: the largest time difference must be >= 0 s, got " + std::to_string(maxDifference_s));
  // The truth's stamps in time order, to find each estimate stamp's candidates by bisection.
  std::vector<std::size_t> truthOrder(truth.size());
  std::iota(truthOrder.begin(), truthOrder.end(), std::size_t{0});
  std::sort(truthOrder.begin(), truthOrder.end(),
            [&](std::size_t a, std::size_t b) { return truth.times_s[a] < truth.times_s[b]; });

  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;  // |dt|, estimate index, truth index
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const double t = estimate.times_s[i];
    auto it = std::lower_bound(truthOrder.begin(), truthOrder.end(), t - maxDifference_s,
                               [&](std::size_t j, double time) { return truth.times_s[j] < time; });
    for (; it != truthOrder.end() && truth.times_s[*it] <= t + maxDifference_s; ++it)
      candidates.emplace_back(std::abs(truth.times_s[*it] - t), i, *it);
  }
  std::sort(candidates.begin(), candidates.end());

  std::vector<bool> estimateUsed(estimate.size(), false), truthUsed(truth.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& [difference, i, j] : candidates) {
    if (estimateUsed[i] || truthUsed[j]) continue;
    estimateUsed[i] = truthUsed[j] = true;
    pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end(),
            [&](const auto& a, const auto& b) { return estimate.times_s[a.first] < estimate.times_s[b.first]; });

  AssociatedTrajectories matched;
  for (const auto& [i, j] : pairs) {
    matched.estimate.add(estimate.times_s[i], estimate.worldFromCamera[i]);
    matched.truth.add(truth.times_s[j], truth.worldFromCamera[j]);
  }
  return matched;
}

AssociatedTrajectories associateByIndex(const Trajectory& estimate, const Trajectory& truth) {
  if (estimate.size() != truth.size())
    throw Error("association by index: the estimate has " + std::to_string(estimate.size()) + " poses, the truth " +
                std::to_string(truth.size()) + "; expected the same count (one pose per frame in both)");
  return {estimate, truth};
}

}  // namespace lrsvo
