#pragma once

#include <cstdint>
#include <string>

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/keyframe_policy.h"
#include "lrsvo/frontend/odometry/long_range_initializer.h"
#include "lrsvo/frontend/odometry/outlier_threshold.h"
#include "lrsvo/frontend/odometry/pose_estimator.h"
#include "lrsvo/frontend/odometry/stereo_start.h"
#include "lrsvo/frontend/odometry/triangulation.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo {

// How the window's bundle adjustment treats the stereo extrinsic S.
enum class ExtrinsicMode {
  kBounded,  // S free inside the rig's box around calibration (the paper's method)
  kFree,     // S free without bounds (the paper's "unconstrained" comparison)
  kRigid,    // S held at calibration (conventional rigid stereo VO, the failing baseline)
};

// Parses "bounded" | "free" | "rigid"; throws lrsvo::Error otherwise.
ExtrinsicMode extrinsicModeFromName(const std::string& name);
const char* extrinsicModeName(ExtrinsicMode mode);

struct OdometryOptions {
  // Sliding window: the most recent keyframes whose poses, points and the
  // shared S one bundle adjustment refines (paper: 12-15 stereo pairs).
  int windowSize = 15;
  int fixedPoses = 1;  // oldest poses of the window held (the gauge)
  // Retired keyframes kept in each adjustment as held views: their base
  // observations of the window's points still count, from fixed orientations,
  // their centres sliding with one shared scale about the oldest keyframe
  // (EdgeProjectHeldView). At long range a window held by its oldest pose alone
  // can tilt its map almost for free (the bas-relief ambiguity), moving its
  // newest keyframe by metres; the held views stop that, and leave the scale
  // to the stereo observations. 0: the window alone.
  int anchorKeyframes = 5;
  // The scale the held views carry is a running estimate over many windows:
  // each adjustment holds it with a prior N(1, P + q^2), P its relative
  // variance so far (from the initialiser's, then each window's marginal) and
  // q this drift allowance per keyframe. At 100 m and more one window's stereo
  // barely measures scale (its disparity is smaller than S's rotation box), so
  // without the prior the scale would jump. 0: no drift allowed.
  double scaleDriftPerKeyframe = 3e-4;
  // How fast S may change, as the prior std of its rate: in the rig's bound
  // half-widths (Rig::tolerance) per second. Each adjustment then estimates S
  // at its newest keyframe and S's rate, older keyframes seeing
  // s + (t - t_newest) * rate, and the next window starts from S moved on at
  // that rate. A rig flexing by its whole box within seconds moves S by
  // pixels across the ~1-2 s a window spans; one constant S lags it and the
  // newest keyframes, triangulated through the lagging S, step too far.
  // 0: one constant S per window (the paper's model).
  double extrinsicRateSigma = 1.0;
  ExtrinsicMode extrinsicMode = ExtrinsicMode::kBounded;
  // The window's constraint method as "name[:setting=value,...]" (makeConstraintMethod), for kBounded: one
  // barrier round per solve, as each window starts from the last one's iterate.
  std::string constraintMethod = "log_barrier:rounds=1";
  // One barrier round: each window starts from the last window's S, already
  // strictly inside and near its optimum, so the interior-point schedule of a
  // cold start (mu decreased over rounds) would only repeat the solve.
  ConstraintSettings constraintSettings{.start = StartPolicy::kProject};
  // Each window adjustment: warm-started, it rarely needs more than 10 iterations; it stops
  // when the cost changes by less than 1e-5 of itself. Two threads (the linearisation,
  // the Hessian and the Schur complement), for the two cores the odometry is built for:
  // the estimates are the same for any count, bit for bit.
  SolverOptions solver{
      .linearSolver = "schur_dense", .lm = {}, .maxIterations = 10, .functionTolerance = 1e-5, .threads = 2};
  BundleGraphOptions bundle;
  // After each window adjustment, an observation whose reprojection error
  // exceeds the window's threshold (outlier_threshold.h: 4 sigma of the
  // window's own noise, within 0.5-4 px; window_outliers.h: a keyframe off as
  // a whole loses its stereo observations instead) is removed, and a track with a
  // base-camera outlier is dropped. A frame's pose drops the tracks farther
  // than outliers.maxThreshold_px from it.
  OutlierTestOptions outliers;

  KeyframePolicyOptions keyframes;

  // New structure: a track is triangulated once its base camera has seen it
  // in this many keyframes of the window (paper: at least 3 sequential views);
  // its secondary observations join as further rays.
  int minTriangulationViews = 3;
  TriangulationOptions triangulation{.maxIterations = 10, .minParallax_rad = 5e-3, .maxReprojectionError_px = 2.0};

  // Pose of every frame: P3P in MLESAC on base observations of mapped points.
  PoseEstimatorOptions pose;
  int minPoseInliers = 20;  // fewer: tracking is lost, and a new initialisation starts
  // A frame without a measured pose (tracking lost) at most this long after
  // the last measured one gets the constant-velocity prediction, marked as
  // predicted: a short loss leaves no hole in the trajectory. 0: none.
  double maxPrediction_s = 2.0;
  // After a loss, each frame up to this long after the last measured pose is
  // first posed against the lost segment's map (P3P in MLESAC on the tracks
  // the front end found again, FeatureTrackerOptions::alignment); a pose takes
  // the segment up again in the same world. A frame without old tracks costs
  // nothing here: the image front end ends the search sooner, once the image
  // before the break is predicted out of view (the same 10 s at most).
  // 0: a loss always starts a new segment.
  double relocaliseWithin_s = 10.0;

  // Where stereo sees depth (close range, low flight), the odometry starts at
  // once from one frame's stereo structure instead (stereo_start.h).
  StereoStartOptions stereoStart;
  // The long-range initialisation: its `frames` frames, the first one
  // buffered and then each at least initializationInterval_s after the last
  // (the paper takes 10 of 30 frames at 30 Hz: 0.1 s apart). A time, not a
  // frame count, so that the start sees the same stretch of flight, and so the
  // same geometry, at any frame rate.
  LongRangeInitializerOptions initializer;
  double initializationInterval_s = 0.1;
  // When the long-range start fails only because its scale is too uncertain
  // (kappa's relative std above initializer.maxKappaRelativeStd), the start
  // takes one more sample and tries again, keeping its frames, as long as the
  // std could fall to the limit within this many samples (it falls about as
  // one over the square root of their count); past that, the oldest frames
  // are given up as for any failure. The window keeps the newest windowSize
  // of the start's keyframes; the ones before are held views.
  int maxInitializationFrames = 30;

  std::uint64_t seed = 1;

  // Throws lrsvo::Error naming the first invalid setting.
  void validate() const;
};

}  // namespace lrsvo
