#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/initialization_result.h"
#include "lrsvo/frontend/odometry/monocular_initializer.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/outlier_threshold.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo {

struct LongRangeInitializerOptions {
  int frames = 10;                               // base frames from the first (paper: 10)
  std::string constraintMethod = "log_barrier";  // "name[:setting=value,...]" (makeConstraintMethod)
  // kProject: the batch that runs again without the outliers starts where
  // the first ended, which may lie nearer a bound than the interior margin.
  ConstraintSettings constraintSettings{.start = StartPolicy::kProject};
  // The batch adjustment (its iteration cap per barrier round); the monocular
  // start uses the same algorithm and linear solver.
  SolverOptions solver{.linearSolver = "schur_dense", .lm = {}, .maxIterations = 100};
  // true: kappa joins every secondary projection (the paper's method);
  // false: control (b), the same batch without kappa, so the map itself must
  // move to the metric scale.
  bool estimateScale = true;
  // Distance given to the first monocular pair, in map units (the paper's
  // unit scale). A study of the start scale sets it to r x the true distance.
  double initialBaseline = 1.0;
  // kappa's start. The map's unit is arbitrary (the first pair's distance);
  // in it the metric baseline c measures c / kappa, so the truth is the first
  // pair's distance in metres over initialBaseline. The paper starts at 1:
  // nothing better is known before the secondary camera is added, and kappa
  // is the well-conditioned direction that absorbs the difference.
  double initialKappa = 1.0;
  // Convergence checks before the map is made metric.
  double maxRmsReprojectionError_px = 2.0;  // per image coordinate, over base and secondary observations
  double maxKappaRelativeStd = 0.1;         // the metric scale's standard deviation over its value
  MonocularOptions monocular;               // its frames, initialBaseline, solver, bundle and seed are set from here
  BundleGraphOptions bundle;
  // The observations the batch gives up after its first solve, as the
  // sliding window judges its own (findWindowOutliers).
  OutlierTestOptions outliers;
  std::uint64_t seed = 1;
};

// The long-range initialisation (docs/method.md, Fig. 14; paper Section 4.3):
//  1. monocular VO over the base camera of the first N frames, the first
//     pair at distance initialBaseline (buildMonocularMaps: one map per
//     motion hypothesis of the pair; steps 2-5 run on each, and of those
//     that pass the checks of step 4 the one with the lowest RMS
//     reprojection error is the result: with kappa free, the wrong motion
//     can fit well by letting kappa grow without bound, the baseline shrink
//     to nothing and S's rotation take up the disparity, which step 4's
//     conditioning check rejects);
//  2. every secondary observation of a mapped point joins the graph
//     (EdgeProjectSecondaryScaled through one VertexStereoExtrinsic per
//     secondary camera, starting at calibration and bounded by the rig's
//     tolerances, and one VertexScale kappa shared by all);
//  3. one batch adjustment over poses, points, extrinsics and kappa within
//     the bounds (optimizeWithBounds). Gauge: pose 0 held, and the distance
//     between poses 0 and 1 held, since scaling the map by a and kappa by
//     1 / a changes no projection. Outliers among its errors (the sliding
//     window's test: a base-camera outlier takes its track out, a secondary
//     one that observation) are then left out, and the batch runs again from
//     where it ended;
//  4. checks: the solve converged, the RMS reprojection error is within its
//     limit, kappa is finite, positive and well conditioned: the relative
//     standard deviation of the metric first-to-last camera distance (kappa
//     times the map's distance, free of the gauge) from the information,
//     conditioned on the extrinsic centres (see 5) and on angles at a bound,
//     is small;
//  5. kappa and the centres c share an exact gauge, (c, kappa) -> (b c, b kappa)
//     changes no projection, pinned only by c's bounds (to 0.14 % for +-1 mm
//     on 0.7 m). The metric unit is therefore the calibrated baseline length:
//     every point and camera position is multiplied by s = kappa |c_cal| / |c|
//     and c by |c_cal| / |c|. With X' = s X, t' = s t, c' = c s / kappa,
//     R_s(R X' + t' - c') = s R_s(R X + t - c / kappa) projects to the same
//     pixel, so the map is metric with kappa = 1.
// With estimateScale false, step 2 uses EdgeProjectSecondary, the distance
// is not held (the baseline sets the unit) and kappa is 1 in steps 4-5.
class LongRangeInitializer {
 public:
  explicit LongRangeInitializer(LongRangeInitializerOptions options);
  const LongRangeInitializerOptions& options() const { return options_; }
  // The options of step 1's monocular VO: `monocular` with its frames, initial baseline,
  // solver, bundle and seed set from these options.
  MonocularOptions monocularOptions() const;

  // Throws lrsvo::Error on an invalid rig or options; reports every other
  // failure in the result (no poses when the monocular stage fails, since its
  // map has no metric scale; the scaled poses when a check fails).
  InitializationResult initialize(const Rig& rig, const std::vector<FrameObservations>& frames) const;

 private:
  using Vector6 = VertexStereoExtrinsic::Vector6;
  // One solve of step 3: the graph, the bounds it kept and its summary.
  struct Batch {
    std::unique_ptr<BundleGraph> bundle;
    Bounds bounds;
    SolverSummary summary;
  };
  // Steps 2-3 on `map` (in its own unit), S and kappa starting at the given values.
  Batch adjust(const Rig& rig, const std::vector<FrameObservations>& frames, const SparseMap& map,
               const std::vector<Vector6>& extrinsics, double kappa) const;
  // Steps 2-5 on one monocular map.
  InitializationResult addSecondaryCameras(const Rig& rig, const std::vector<FrameObservations>& frames,
                                           const SparseMap& monocularMap) const;

  LongRangeInitializerOptions options_;
};

}  // namespace lrsvo
