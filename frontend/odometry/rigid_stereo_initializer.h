#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/initialization_result.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/pose_estimator.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/frontend/odometry/triangulation.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo {

struct RigidStereoInitializerOptions {
  int frames = 10;
  int minPoints = 20;  // valid stereo triangulations in the first frame, and mapped points a frame must see
  PoseEstimatorOptions pose;
  // A stereo point needs rays 1 mrad apart (depth up to ~1000 baselines)
  // and an RMS reprojection error of at most 3 px in the rigid rig.
  TriangulationOptions triangulation{.maxIterations = 10, .minParallax_rad = 1e-3, .maxReprojectionError_px = 3.0};
  BundleGraphOptions bundle;
  SolverOptions solver{.linearSolver = "schur_dense", .lm = {}, .maxIterations = 50};  // each bundle adjustment
  // A final RMS reprojection error (per image coordinate) above this fails:
  // a rig deformed away from its calibration shows up here.
  double maxRmsReprojectionError_px = 2.0;
  std::uint64_t seed = 1;
};

// The paper's control (a), a conventional stereo VO start (Section 4.3.1):
// points triangulated from the first stereo pair with the calibrated (rigid)
// extrinsic; then for each next frame its pose by P3P in MLESAC from base
// observations of mapped points, new points triangulated from that frame's
// stereo pair, and a bundle adjustment over the frames so far with the
// extrinsic held at calibration (pose 0 held; the baseline sets the scale).
// At long range it legitimately fails (few valid triangulations, poses the
// wrong points cannot support, a final RMS reprojection error above its
// limit): the result then says why and keeps the frames reached, so a study
// can still score the last pose.
class RigidStereoInitializer {
 public:
  explicit RigidStereoInitializer(RigidStereoInitializerOptions options);
  const RigidStereoInitializerOptions& options() const { return options_; }

  // Throws lrsvo::Error on an invalid rig or options only.
  InitializationResult initialize(const Rig& rig, const std::vector<FrameObservations>& frames) const;

 private:
  RigidStereoInitializerOptions options_;
};

}  // namespace lrsvo
