#include "lrsvo/frontend/odometry/motion_model.h"

#include "lrsvo/graph/error.h"

namespace lrsvo {

void ConstantVelocity::add(double time_s, const Eigen::Isometry3d& worldFromCamera) {
  if (!poses_.empty() && time_s < poses_.back().first) throw Error("constant velocity: times must not decrease");
  if (!poses_.empty() && time_s == poses_.back().first) poses_.pop_back();
  poses_.emplace_back(time_s, worldFromCamera);
  while (poses_.size() > 2 && poses_[1].first <= time_s - span_s_) poses_.pop_front();
}

Eigen::Isometry3d ConstantVelocity::predict(double time_s) const {
  if (poses_.empty()) throw Error("constant velocity: no pose to predict from");
  const auto& [lastTime, last] = poses_.back();
  if (poses_.size() < 2) return last;
  const auto& [firstTime, first] = poses_.front();
  const double fraction = (time_s - lastTime) / (lastTime - firstTime);
  const Eigen::AngleAxisd turn(first.linear().transpose() * last.linear());  // in the camera's axes
  Eigen::Isometry3d predicted = last;
  predicted.translation() += fraction * (last.translation() - first.translation());
  predicted.linear() = last.linear() * Eigen::AngleAxisd(fraction * turn.angle(), turn.axis()).toRotationMatrix();
  return predicted;
}

}  // namespace lrsvo
