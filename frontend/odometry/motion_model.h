#pragma once

#include <deque>
#include <utility>

#include <Eigen/Geometry>

namespace lrsvo {

// Constant velocity of the base camera, from its recent measured poses: the
// centre moves at the velocity between the oldest and the newest pose of the
// last `span_s` seconds, and the attitude turns at their relative rotation's
// rate (about the camera's own axes). Frame-to-frame poses carry centimetres
// of noise; differencing over the span rather than over one frame keeps that
// noise out of the velocity.
class ConstantVelocity {
 public:
  explicit ConstantVelocity(double span_s = 0.5) : span_s_(span_s) {}
  // A measured pose (world-from-camera) at time t; times must not decrease.
  void add(double time_s, const Eigen::Isometry3d& worldFromCamera);
  void clear() { poses_.clear(); }
  // Whether a pose is known at all (predict() then holds at least the last one).
  bool known() const { return !poses_.empty(); }
  double lastTime() const { return poses_.back().first; }
  // The pose at time t: the last one moved on at the current velocity (held
  // still with a single pose). Needs known().
  Eigen::Isometry3d predict(double time_s) const;

 private:
  double span_s_;
  std::deque<std::pair<double, Eigen::Isometry3d>> poses_;  // oldest first, within span_s of the newest
};

}  // namespace lrsvo
