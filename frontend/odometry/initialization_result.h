#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/graph/solver_summary.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// What an initialiser (long-range or rigid stereo) hands to the odometry.
// The world is the first base camera's frame, in metres.
struct InitializationResult {
  bool success = false;
  std::string failure;  // why not, when !success
  // Base camera-from-world of every frame reached (all requested frames on
  // success; on failure those before it, which a study may still score).
  std::vector<Eigen::Isometry3d> cameraFromWorld;
  std::map<int, Eigen::Vector3d> points;                   // by track id
  std::vector<VertexStereoExtrinsic::Vector6> extrinsics;  // [k - 1] for secondary camera k
  // The factor that made the map metric (long-range: kappa |c_cal| / |c|, the
  // map's unit in metres; 1 for the rigid stereo start), and the relative
  // standard deviation of the scale it gives (of the metric distance from the
  // first to the last camera) from the information; 0 when kappa is not estimated.
  double kappa = 1.0;
  double kappaRelativeStd = 0.0;
  // It failed only because kappaRelativeStd exceeds its limit: the frames fit,
  // and more frames of the same flight would tell the scale better.
  bool scaleTooUncertain = false;
  SolverSummary summary;                 // the final bundle adjustment
  double rmsReprojectionError_px = 0.0;  // per image coordinate, over every observation in that adjustment
};

// Whether `candidate` is a better start than `other`, both from the same
// frames (one per motion hypothesis): one that passes its initialiser's
// checks beats one that does not, then the lower RMS reprojection error wins.
bool isBetterStart(const InitializationResult& candidate, const InitializationResult& other);

// Ground-truth camera-from-world poses re-expressed with the first camera's
// frame as the world (T_i T_0^-1), the frame an initialiser's result is in;
// e.g. the final position error is |C_last(result) - C_last(aligned truth)|.
std::vector<Eigen::Isometry3d> alignToFirstCamera(const std::vector<Eigen::Isometry3d>& trueCameraFromWorld);

}  // namespace lrsvo
