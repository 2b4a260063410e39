#pragma once

#include <map>
#include <string>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/frontend/odometry/triangulation.h"

namespace lrsvo {

// Points from one frame's stereo pairs: every track its base camera saw and
// at least one secondary camera matched, triangulated through the rig's
// calibration with the base camera at `baseFromWorld` (world coordinates).
// Tracks in `known` are left out; invalid triangulations are dropped.
std::map<int, Eigen::Vector3d> triangulateAcrossRig(const Rig& rig, const Eigen::Isometry3d& baseFromWorld,
                                                    const FrameObservations& frame, const TriangulationOptions& options,
                                                    const std::map<int, Eigen::Vector3d>& known = {});

struct StereoStartOptions {
  // The odometry starts from one frame's stereo structure when the scene's
  // median depth is at most this many baselines, and from the long-range
  // (kappa) initialisation beyond. A rotation error q of the extrinsic (the
  // rig's tolerance, 10 mrad by default) shifts every disparity by f q, so a
  // stereo depth is off by q z / b relative: at 40 baselines that is within
  // 40 %, which the window's bounded S then corrects as the camera moves, and
  // there the stereo rays still meet at 25 mrad. Farther out (the paper's
  // Fig. 17: a rigid-stereo start fails above about 57 baselines, 40 m on
  // 0.7 m) the multi-view long-range start is the better one. Close range
  // needs the stereo start in any case: a still or hovering camera gives the
  // monocular stage of the long-range start no parallax. 0: never.
  double maxDepthOverBaseline = 40.0;
  int minPoints = 30;  // valid stereo points needed
  // Rays at least 1 mrad apart (depths up to ~1000 baselines), RMS error at most 2 px in the calibrated rig.
  TriangulationOptions triangulation{.maxIterations = 10, .minParallax_rad = 1e-3, .maxReprojectionError_px = 2.0};

  // Throws lrsvo::Error naming the first invalid setting.
  void validate() const;
};

// What one frame's stereo pairs say about starting from them.
struct StereoStart {
  bool usable = false;
  std::string reason;                     // why not, when !usable
  std::map<int, Eigen::Vector3d> points;  // in the frame's base camera coordinates
  double medianDepthOverBaseline = 0.0;   // of the points (0 without any)
  // The relative standard deviation of the map's scale this start gives: the
  // extrinsic's rotation tolerance q, uniform in +-q, spreads depths by
  // +-q z / b, so q (z / b) / sqrt(3) at the median depth.
  double scaleRelativeStd = 0.0;
};

// Triangulates the frame's stereo pairs (the base camera at the origin) and
// decides whether the odometry may start from them (StereoStartOptions).
StereoStart startFromStereo(const Rig& rig, const FrameObservations& frame, const StereoStartOptions& options);

}  // namespace lrsvo
