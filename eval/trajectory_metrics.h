#pragma once

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrsvo/eval/trajectory_alignment.h"
#include "lrsvo/eval/trajectory_association.h"

namespace lrsvo {

// RMSE, mean, median and largest of a set of errors; NaN (count 0) when empty.
struct ErrorStatistics {
  std::size_t count = 0;
  double rmse = std::numeric_limits<double>::quiet_NaN();
  double mean = std::numeric_limits<double>::quiet_NaN();
  double median = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};
ErrorStatistics errorStatistics(std::vector<double> errors);

// Path length of a trajectory: the sum of its position steps.
double pathLength(const Trajectory& trajectory);

// Per pose after alignment: |p_i - q_i| (m) and the angle of R_q_i^T R_p_i (rad),
// p the estimate, q the truth, matched pose by pose.
std::vector<double> positionErrors(const Trajectory& estimate, const Trajectory& truth);
std::vector<double> orientationErrors(const Trajectory& estimate, const Trajectory& truth);

// Index pairs (i, j) over which relative poses are compared, as evo defines
// them (its filters for `--delta_unit f` and `m`). By frames: j = i + delta;
// `allPairs` starts a pair at every frame, otherwise the pairs are chained.
// By distance, along `path` (evo: the estimate): chained, the path is walked
// from its first pose and a mark set each time the length walked since the
// last mark (or the start) reaches delta_m; the pairs join consecutive marks,
// so the first starts where the path first reaches delta_m. With `allPairs`,
// each i pairs with the later j whose path length from i is nearest delta_m,
// when within relativeTolerance * delta_m of it.
using IndexPairs = std::vector<std::pair<std::size_t, std::size_t>>;
IndexPairs pairsByFrames(std::size_t poses, int delta, bool allPairs);
IndexPairs pairsByDistance(const Trajectory& path, double delta_m, bool allPairs, double relativeTolerance = 0.1);

// Relative pose errors E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), P the estimate and Q
// the truth: |translation of E| (m) and the rotation angle of E (rad) per pair.
struct RelativePoseErrors {
  std::vector<double> translation_m;
  std::vector<double> rotation_rad;
};
RelativePoseErrors relativePoseErrors(const Trajectory& estimate, const Trajectory& truth, const IndexPairs& pairs);

// KITTI odometry devkit's drift: segments of each length (path length along
// the truth) starting every `stepFrames`-th frame and ending at the first frame
// past the length; per segment the relative pose error divided by the length.
struct DriftAtLength {
  double length_m = 0.0;
  std::size_t segments = 0;
  double translation_percent = 0.0;    // mean |t_err| / length x 100
  double rotation_deg_per_100m = 0.0;  // mean angle / length, in deg per 100 m
};
struct KittiDrift {
  std::vector<DriftAtLength> perLength;  // only the lengths with at least one segment
  std::size_t segments = 0;
  double translation_percent = std::numeric_limits<double>::quiet_NaN();  // mean over all segments; NaN: none fits
  double rotation_deg_per_100m = std::numeric_limits<double>::quiet_NaN();
};
std::vector<double> kittiSegmentLengths();  // 100, 200, ..., 800 m
KittiDrift kittiDrift(const Trajectory& estimate, const Trajectory& truth, const std::vector<double>& lengths_m,
                      int stepFrames = 10);

// Whose path the RPE's distance step is measured along: the estimate's, as
// evo does, or the truth's (independent of the estimate's errors).
enum class RpePath { kEstimate, kTruth };

struct TrajectoryMetricsOptions {
  int rpeDeltaFrames = 1;
  double rpeDelta_m = 100.0;
  bool rpeAllPairs = false;
  RpePath rpePath = RpePath::kEstimate;
  std::vector<double> driftLengths_m = kittiSegmentLengths();
};

// Everything `lrsvo eval` reports of an estimate against the truth.
struct TrajectoryMetrics {
  TrajectoryMetricsOptions options;
  std::size_t frames = 0;   // matched poses
  double distance_m = 0.0;  // path length of the truth
  Alignment se3, sim3;
  ErrorStatistics ate_m, ateRotation_rad;  // after the SE3 alignment
  ErrorStatistics ateSim3_m;
  ErrorStatistics rpeTranslation_m, rpeRotation_rad;                  // delta in frames
  ErrorStatistics rpeDistanceTranslation_m, rpeDistanceRotation_rad;  // delta in metres
  KittiDrift drift;
  double scaleErrorPercent = 0.0;          // 100 (1 / s - 1), s the Sim3 alignment's scale (truth ~ s R est + t)
  double pathLengthErrorPercent = 0.0;     // 100 (L_estimate / L_truth - 1), L the path lengths
  double finalPositionError_m = 0.0;       // at the last pose, start-aligned
  double finalPositionErrorPercent = 0.0;  // of distance_m
};

// Needs at least 2 matched poses; throws lrsvo::Error otherwise.
TrajectoryMetrics computeTrajectoryMetrics(const AssociatedTrajectories& matched,
                                           const TrajectoryMetricsOptions& options = {});

// Flat keys (ate_rmse_m, drift_percent, ...); NaN becomes null. Angles in degrees.
nlohmann::json toJson(const TrajectoryMetrics& metrics);

}  // namespace lrsvo
