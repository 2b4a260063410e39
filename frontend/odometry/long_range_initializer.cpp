#include "lrsvo/frontend/odometry/long_range_initializer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "lrsvo/frontend/odometry/window_outliers.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/marginal_covariance.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

void validate(const LongRangeInitializerOptions& o) {
  if (o.frames < 3) throw Error("long-range initialiser: needs at least 3 frames, got " + std::to_string(o.frames));
  if (!(o.initialBaseline > 0.0) || !(o.initialKappa > 0.0))
    throw Error("long-range initialiser: initialBaseline and initialKappa must be positive");
  try {
    (void)makeConstraintMethod(o.constraintMethod);
  } catch (const Error& e) {
    throw Error("long-range initialiser: " + std::string(e.what()));
  }
  o.solver.validate();
  validate(o.outliers);
}

// The relative standard deviation of the metric scale, as that of the metric
// distance between the first and last cameras, kappa L: along the gauge the
// map's unit and kappa trade off exactly, so kappa alone would carry the
// distance prior's own spread, which the product cancels. Conditioned on the
// extrinsic centres and on angles at a bound (see the class comment).
double scaleRelativeStd(BundleGraph& bundle, const Bounds& bounds, int lastPose, int threads) {
  const std::vector<HeldCoordinate> held = bundle.scaleGaugeCoordinates(&bounds);
  const VertexPose& last = *bundle.pose(lastPose);
  // d(kappa L) / (kappa L) = dkappa / kappa + dL / L; pose 0 is fixed and the
  // last centre moves by -R^T dt under VertexPose's update.
  const Eigen::Vector3d span = last.centre() - bundle.pose(0)->centre();
  Eigen::VectorXd jacobian = Eigen::VectorXd::Zero(7);
  jacobian[0] = 1.0 / bundle.scale()->kappa();
  jacobian.segment<3>(1) = -last.rotation() * span / span.squaredNorm();
  return std::sqrt(marginalVariance(bundle.graph(), {bundle.scale(), &last}, jacobian, held, threads));
}

}  // namespace

LongRangeInitializer::LongRangeInitializer(LongRangeInitializerOptions options) : options_(std::move(options)) {
  validate(options_);
}

MonocularOptions LongRangeInitializer::monocularOptions() const {
  const LongRangeInitializerOptions& o = options_;
  MonocularOptions monocular = o.monocular;
  monocular.frames = o.frames;
  monocular.initialBaseline = o.initialBaseline;
  monocular.solver.algorithm = o.solver.algorithm;
  monocular.solver.linearSolver = o.solver.linearSolver;
  monocular.bundle = o.bundle;
  monocular.seed = o.seed;
  return monocular;
}

InitializationResult LongRangeInitializer::initialize(const Rig& rig,
                                                      const std::vector<FrameObservations>& frames) const {
  rig.validate();
  if (rig.secondaryCount() < 1) throw Error("long-range initialiser: the rig needs a secondary camera");
  const std::vector<MonocularResult> maps = buildMonocularMaps(rig, frames, monocularOptions());

  // The secondary camera judges the pair's motion hypotheses: its calibrated
  // offset along the baseline fits the true motion only, so the planar twin
  // leaves a large reprojection error even with S at its bounds, or fits
  // only with a kappa so large that its conditioning check fails.
  std::optional<InitializationResult> best;
  for (const MonocularResult& monocular : maps) {
    if (!monocular.success) continue;
    InitializationResult candidate = addSecondaryCameras(rig, frames, monocular.map);
    if (!best || isBetterStart(candidate, *best)) best = std::move(candidate);
  }
  if (best) return std::move(*best);
  InitializationResult result;
  result.failure = "long-range: " + maps.front().failure;
  return result;
}

LongRangeInitializer::Batch LongRangeInitializer::adjust(const Rig& rig, const std::vector<FrameObservations>& frames,
                                                         const SparseMap& map, const std::vector<Vector6>& extrinsics,
                                                         double kappa) const {
  const LongRangeInitializerOptions& o = options_;
  Batch batch{std::make_unique<BundleGraph>(rig, map, 1, o.bundle), {}, {}};
  BundleGraph& bundle = *batch.bundle;
  for (int k = 1; k <= rig.secondaryCount(); ++k) bundle.addExtrinsic(k, extrinsics[k - 1], false);
  if (o.estimateScale) {
    bundle.addScale(kappa);
    bundle.holdDistance(0, 1);
  }
  for (int i = 0; i < o.frames; ++i) bundle.addObservations(i, frames[i]);
  batch.bounds = bundle.extrinsicBounds();
  batch.summary = optimizeWithBounds(bundle.graph(), o.solver, batch.bounds, o.constraintMethod, o.constraintSettings);
  return batch;
}

InitializationResult LongRangeInitializer::addSecondaryCameras(const Rig& rig,
                                                               const std::vector<FrameObservations>& frames,
                                                               const SparseMap& monocularMap) const {
  const LongRangeInitializerOptions& o = options_;
  Batch batch = adjust(rig, frames, monocularMap, rig.extrinsics, o.initialKappa);

  // A track that is no fixed point, or a wrong stereo match, misses by pixels
  // to tens of pixels among sub-pixel errors; the robust kernel bounds its
  // pull, but not the RMS the checks and the choice between motions read. As
  // in the sliding window, a base-camera outlier takes its track out and a
  // secondary one that observation; the batch then runs once more without
  // them, from where it ended.
  const WindowOutliers outliers = findWindowOutliers(
      batch.bundle->projectionErrors(), static_cast<int>(rig.cameras.size()), o.outliers, batch.summary.converged());
  if (!outliers.rejectedTracks.empty() || !outliers.secondaryOutliers.empty()) {
    std::vector<FrameObservations> inliers(frames.begin(), frames.begin() + o.frames);
    for (std::size_t i = 0; i < inliers.size(); ++i)
      std::erase_if(inliers[i].observations, [&](const Observation& observation) {
        return outliers.condemns(static_cast<int>(i), observation);
      });
    SparseMap map = batch.bundle->map();
    for (int track : outliers.rejectedTracks) map.points.erase(track);
    const double kappa = o.estimateScale ? batch.bundle->scale()->kappa() : 1.0;
    Batch again = adjust(rig, inliers, map, batch.bundle->extrinsics(), kappa);
    appendSummary(batch.summary, again.summary);
    again.summary = std::move(batch.summary);
    batch = std::move(again);
  }

  InitializationResult result;
  result.summary = batch.summary;
  BundleGraph& bundle = *batch.bundle;
  const Bounds& bounds = batch.bounds;
  result.rmsReprojectionError_px = bundle.rmsReprojectionError_px();
  result.extrinsics = bundle.extrinsics();

  std::string failure;
  if (!result.summary.converged())
    failure =
        std::string("the batch adjustment did not converge (") + terminationName(result.summary.termination) + ")";
  else if (!(result.rmsReprojectionError_px <= o.maxRmsReprojectionError_px))
    failure = "RMS reprojection error " + format("%.3g", result.rmsReprojectionError_px) + " px exceeds " +
              format("%.3g", o.maxRmsReprojectionError_px) + " px";

  // kappa and the extrinsic centres share an exact gauge: (c, kappa) -> (b c, b kappa) changes no projection
  // (nor, without kappa, (c, map) -> (b c, b map)). Only c's bounds pin it, to +-q / |c| (0.14 % for 1 mm on
  // 0.7 m); without bounds it is free. So the metric unit comes from the calibrated baseline length: the map is
  // multiplied by kappa |c_cal| / |c| and each c by |c_cal| / |c|, which keeps every projection.
  const double kappa = o.estimateScale ? bundle.scale()->kappa() : 1.0;
  double calibratedLength = 0.0, estimatedLength = 0.0;
  for (int k = 0; k < rig.secondaryCount(); ++k) {
    calibratedLength += rig.extrinsics[k].head<3>().norm();
    estimatedLength += result.extrinsics[k].head<3>().norm();
  }
  const double toCalibratedLength = calibratedLength / estimatedLength;
  result.kappa = kappa * toCalibratedLength;
  if (!(std::isfinite(result.kappa) && result.kappa > 0.0)) {
    result.failure = "long-range: the map's scale " + format("%g", result.kappa) + " is not positive and finite";
    return result;
  }
  if (o.estimateScale) {
    try {
      result.kappaRelativeStd = scaleRelativeStd(bundle, bounds, o.frames - 1, o.solver.threads);
    } catch (const Error&) {
      result.kappaRelativeStd = std::numeric_limits<double>::infinity();
    }
    if (failure.empty() && !(result.kappaRelativeStd <= o.maxKappaRelativeStd)) {
      failure = "kappa is poorly conditioned: relative standard deviation " + format("%.3g", result.kappaRelativeStd) +
                " exceeds " + format("%.3g", o.maxKappaRelativeStd);
      result.scaleTooUncertain = true;
    }
  }
  for (auto& extrinsic : result.extrinsics) extrinsic.head<3>() *= toCalibratedLength;
  SparseMap map = bundle.map();
  map.scale(result.kappa);
  result.cameraFromWorld = std::move(map.cameraFromWorld);
  result.points = std::move(map.points);
  result.success = failure.empty();
  if (!result.success) result.failure = "long-range: " + failure;
  return result;
}

}  // namespace lrsvo
