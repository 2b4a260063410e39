#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

namespace lrsvo {

// One measurement of a tracked feature: which point (track id), which camera
// of the rig (0 = base) and where, in pixels of the undistorted image.
struct Observation {
  int track = -1;
  int camera = 0;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

// Everything measured at one time step: the features tracked in each camera.
// This is what the feature-level simulator (sim/) and the image front end both
// produce, and what the initialisers and the odometry consume.
struct FrameObservations {
  double time_s = 0.0;
  std::vector<Observation> observations;
};

// Slack for "at least T after" between frame times: timestamps from a data
// set carry microseconds of jitter, and n / rate in floating point misses T by
// an ulp, so the frame due at T would fall just short of it.
inline constexpr double kFrameTimeSlack_s = 1e-3;

// The secondary cameras' observations of a frame given with its base
// observations alone, fetched only when needed (Odometry::process).
using SecondaryObservations = std::function<std::vector<Observation>()>;

}  // namespace lrsvo
