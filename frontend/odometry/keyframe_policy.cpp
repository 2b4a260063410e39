#include "lrsvo/frontend/odometry/keyframe_policy.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace lrsvo {

bool KeyframePolicy::isKeyframe(const FrameObservations& lastKeyframe, const FrameObservations& frame) const {
  const double interval_s = frame.time_s - lastKeyframe.time_s;
  if (interval_s < options_.minInterval_s - kFrameTimeSlack_s) return false;
  if (interval_s >= options_.maxInterval_s - kFrameTimeSlack_s) return true;
  std::unordered_map<int, Eigen::Vector2d> previous;
  for (const Observation& observation : lastKeyframe.observations)
    if (observation.camera == 0) previous.emplace(observation.track, observation.pixel);
  if (previous.empty()) return true;
  std::vector<double> motion;
  for (const Observation& observation : frame.observations) {
    if (observation.camera != 0) continue;
    auto match = previous.find(observation.track);
    if (match != previous.end()) motion.push_back((observation.pixel - match->second).norm());
  }
  if (static_cast<double>(motion.size()) < options_.minSharedFraction * static_cast<double>(previous.size()))
    return true;
  auto middle = motion.begin() + static_cast<std::ptrdiff_t>(motion.size() / 2);
  std::nth_element(motion.begin(), middle, motion.end());
  return *middle >= options_.minMedianMotion_px;
}

}  // namespace lrsvo
