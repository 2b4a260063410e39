#include "lrsvo/eval/trajectory_metrics.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "lrsvo/graph/error.h"

namespace lrsvo {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

double rotationAngle(const Eigen::Matrix3d& rotation) { return Eigen::AngleAxisd(rotation).angle(); }

// Path length along `trajectory` from its first pose to each pose.
std::vector<double> cumulativeDistances(const Trajectory& trajectory) {
  std::vector<double> distances(trajectory.size(), 0.0);
  for (std::size_t i = 1; i < trajectory.size(); ++i)
    distances[i] =
        distances[i - 1] +
        (trajectory.worldFromCamera[i].translation() - trajectory.worldFromCamera[i - 1].translation()).norm();
  return distances;
}

// The pose error of the motion from i to j: E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j).
Eigen::Isometry3d relativePoseError(const Trajectory& estimate, const Trajectory& truth, std::size_t i, std::size_t j) {
  const Eigen::Isometry3d estimated = estimate.worldFromCamera[i].inverse() * estimate.worldFromCamera[j];
  const Eigen::Isometry3d actual = truth.worldFromCamera[i].inverse() * truth.worldFromCamera[j];
  return actual.inverse() * estimated;
}

ErrorStatistics scaled(ErrorStatistics statistics, double factor) {
  statistics.rmse *= factor;
  statistics.mean *= factor;
  statistics.median *= factor;
  statistics.max *= factor;
  return statistics;
}

nlohmann::json numberOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

// prefix_rmse<unit>, prefix_mean<unit>, ... of `statistics` times `factor`.
void addStatistics(nlohmann::json& json, const std::string& prefix, const std::string& unit,
                   const ErrorStatistics& statistics, double factor = 1.0) {
  const ErrorStatistics s = scaled(statistics, factor);
  json[prefix + "_rmse" + unit] = numberOrNull(s.rmse);
  json[prefix + "_mean" + unit] = numberOrNull(s.mean);
  json[prefix + "_median" + unit] = numberOrNull(s.median);
  json[prefix + "_max" + unit] = numberOrNull(s.max);
}

}  // namespace

ErrorStatistics errorStatistics(std::vector<double> errors) {
  ErrorStatistics statistics;
  statistics.count = errors.size();
  if (errors.empty()) return statistics;
  const double n = static_cast<double>(errors.size());
  double sumOfSquares = 0.0;
  for (double e : errors) sumOfSquares += e * e;
  statistics.rmse = std::sqrt(sumOfSquares / n);
  statistics.mean = std::accumulate(errors.begin(), errors.end(), 0.0) / n;
  std::sort(errors.begin(), errors.end());
  const std::size_t middle = errors.size() / 2;
  statistics.median = errors.size() % 2 == 1 ? errors[middle] : 0.5 * (errors[middle - 1] + errors[middle]);
  statistics.max = errors.back();
  return statistics;
}

double pathLength(const Trajectory& trajectory) {
  return trajectory.size() == 0 ? 0.0 : cumulativeDistances(trajectory).back();
}

std::vector<double> positionErrors(const Trajectory& estimate, const Trajectory& truth) {
  std::vector<double> errors;
  for (std::size_t i = 0; i < std::min(estimate.size(), truth.size()); ++i)
    errors.push_back((estimate.worldFromCamera[i].translation() - truth.worldFromCamera[i].translation()).norm());
  return errors;
}

std::vector<double> orientationErrors(const Trajectory& estimate, const Trajectory& truth) {
  std::vector<double> errors;
  for (std::size_t i = 0; i < std::min(estimate.size(), truth.size()); ++i)
    errors.push_back(
        rotationAngle(truth.worldFromCamera[i].linear().transpose() * estimate.worldFromCamera[i].linear()));
  return errors;
}

IndexPairs pairsByFrames(std::size_t poses, int delta, bool allPairs) {
  if (delta < 1) throw Error("relative pose error: delta must be at least 1 frame, got " + std::to_string(delta));
  const auto step = static_cast<std::size_t>(delta);
  IndexPairs pairs;
  for (std::size_t i = 0; i + step < poses; i += allPairs ? 1 : step) pairs.emplace_back(i, i + step);
  return pairs;
}

IndexPairs pairsByDistance(const Trajectory& path, double delta_m, bool allPairs, double relativeTolerance) {
  if (!(delta_m > 0.0)) throw Error("relative pose error: delta must be > 0 m, got " + std::to_string(delta_m));
  IndexPairs pairs;
  if (path.size() < 2) return pairs;
  if (allPairs) {
    const std::vector<double> distances = cumulativeDistances(path);
    const double tolerance = relativeTolerance * delta_m;
    for (std::size_t i = 0; i + 1 < distances.size(); ++i) {
      // Path lengths from i only grow: the nearest to delta is at the first
      // j reaching it or the one before.
      const auto reach = std::lower_bound(distances.begin() + static_cast<std::ptrdiff_t>(i) + 1, distances.end(),
                                          distances[i] + delta_m);
      std::size_t best = static_cast<std::size_t>(reach - distances.begin());
      if (best == distances.size() || (best > i + 1 && std::abs(distances[best - 1] - distances[i] - delta_m) <=
                                                           std::abs(distances[best] - distances[i] - delta_m)))
        --best;
      if (std::abs(distances[best] - distances[i] - delta_m) <= tolerance) pairs.emplace_back(i, best);
    }
    return pairs;
  }
  std::vector<std::size_t> marks;
  double walked = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    walked += (path.worldFromCamera[i].translation() - path.worldFromCamera[i - 1].translation()).norm();
    if (walked >= delta_m) {
      marks.push_back(i);
      walked = 0.0;
    }
  }
  for (std::size_t k = 0; k + 1 < marks.size(); ++k) pairs.emplace_back(marks[k], marks[k + 1]);
  return pairs;
}

RelativePoseErrors relativePoseErrors(const Trajectory& estimate, const Trajectory& truth, const IndexPairs& pairs) {
  RelativePoseErrors errors;
  for (const auto& [i, j] : pairs) {
    if (i >= estimate.size() || j >= estimate.size() || i >= truth.size() || j >= truth.size())
      throw Error("relative pose error: pair (" + std::to_string(i) + ", " + std::to_string(j) +
                  ") outside the matched trajectories");
    const Eigen::Isometry3d error = relativePoseError(estimate, truth, i, j);
    errors.translation_m.push_back(error.translation().norm());
    errors.rotation_rad.push_back(rotationAngle(error.linear()));
  }
  return errors;
}

std::vector<double> kittiSegmentLengths() { return {100.0, 200.0, 300.0, 400.0, 500.0, 600.0, 700.0, 800.0}; }

KittiDrift kittiDrift(const Trajectory& estimate, const Trajectory& truth, const std::vector<double>& lengths_m,
                      int stepFrames) {
  if (stepFrames < 1) throw Error("KITTI drift: the step must be at least 1 frame, got " + std::to_string(stepFrames));
  const std::vector<double> distances = cumulativeDistances(truth);
  KittiDrift drift;
  double translationSum = 0.0, rotationSum = 0.0;
  for (double length : lengths_m) {
    if (!(length > 0.0)) throw Error("KITTI drift: segment lengths must be > 0 m, got " + std::to_string(length));
    DriftAtLength atLength;
    atLength.length_m = length;
    double translation = 0.0, rotation = 0.0;  // sums of the per-metre errors
    for (std::size_t first = 0; first < distances.size(); first += static_cast<std::size_t>(stepFrames)) {
      // The devkit's last frame: the first one strictly farther than `length` along the truth.
      const auto last = std::upper_bound(distances.begin() + static_cast<std::ptrdiff_t>(first), distances.end(),
                                         distances[first] + length);
      if (last == distances.end()) continue;
      const Eigen::Isometry3d error =
          relativePoseError(estimate, truth, first, static_cast<std::size_t>(last - distances.begin()));
      translation += error.translation().norm() / length;
      rotation += rotationAngle(error.linear()) / length;
      ++atLength.segments;
    }
    if (atLength.segments == 0) continue;
    const double n = static_cast<double>(atLength.segments);
    atLength.translation_percent = 100.0 * translation / n;
    atLength.rotation_deg_per_100m = 100.0 * kDegreesPerRadian * rotation / n;
    drift.perLength.push_back(atLength);
    drift.segments += atLength.segments;
    translationSum += translation;
    rotationSum += rotation;
  }
  if (drift.segments > 0) {
    const double n = static_cast<double>(drift.segments);
    drift.translation_percent = 100.0 * translationSum / n;
    drift.rotation_deg_per_100m = 100.0 * kDegreesPerRadian * rotationSum / n;
  }
  return drift;
}

TrajectoryMetrics computeTrajectoryMetrics(const AssociatedTrajectories& matched,
                                           const TrajectoryMetricsOptions& options) {
  const Trajectory& estimate = matched.estimate;
  const Trajectory& truth = matched.truth;
  if (estimate.size() != truth.size() || estimate.size() < 2)
    throw Error("trajectory metrics: " + std::to_string(estimate.size()) + " estimated and " +
                std::to_string(truth.size()) + " true poses matched; expected the same count, at least 2");
  TrajectoryMetrics metrics;
  metrics.options = options;
  metrics.frames = estimate.size();
  metrics.distance_m = pathLength(truth);

  metrics.se3 = alignTrajectories(estimate, truth, AlignmentKind::kSE3);
  const Trajectory se3Aligned = transformed(estimate, metrics.se3);
  metrics.ate_m = errorStatistics(positionErrors(se3Aligned, truth));
  metrics.ateRotation_rad = errorStatistics(orientationErrors(se3Aligned, truth));
  metrics.sim3 = alignTrajectories(estimate, truth, AlignmentKind::kSim3);
  metrics.ateSim3_m = errorStatistics(positionErrors(transformed(estimate, metrics.sim3), truth));

  const RelativePoseErrors byFrames =
      relativePoseErrors(estimate, truth, pairsByFrames(metrics.frames, options.rpeDeltaFrames, options.rpeAllPairs));
  metrics.rpeTranslation_m = errorStatistics(byFrames.translation_m);
  metrics.rpeRotation_rad = errorStatistics(byFrames.rotation_rad);
  const RelativePoseErrors byDistance =
      relativePoseErrors(estimate, truth,
                         pairsByDistance(options.rpePath == RpePath::kEstimate ? estimate : truth, options.rpeDelta_m,
                                         options.rpeAllPairs));
  metrics.rpeDistanceTranslation_m = errorStatistics(byDistance.translation_m);
  metrics.rpeDistanceRotation_rad = errorStatistics(byDistance.rotation_rad);

  metrics.drift = kittiDrift(estimate, truth, options.driftLengths_m);
  // The estimate's size against the truth's from the least-squares similarity
  // (truth ~ s R estimate + t); path lengths also count the estimate's
  // frame-to-frame jitter, which inflates them, so they are reported apart.
  metrics.scaleErrorPercent = 100.0 * (1.0 / metrics.sim3.scale - 1.0);
  metrics.pathLengthErrorPercent = 100.0 * (pathLength(estimate) / metrics.distance_m - 1.0);
  const Trajectory startAligned = transformed(estimate, alignFirstPose(estimate, truth));
  metrics.finalPositionError_m = positionErrors(startAligned, truth).back();
  metrics.finalPositionErrorPercent = 100.0 * metrics.finalPositionError_m / metrics.distance_m;
  return metrics;
}

nlohmann::json toJson(const TrajectoryMetrics& metrics) {
  nlohmann::json json;
  json["frames"] = metrics.frames;
  json["distance_m"] = metrics.distance_m;
  addStatistics(json, "ate", "_m", metrics.ate_m);
  addStatistics(json, "ate_rot", "_deg", metrics.ateRotation_rad, kDegreesPerRadian);
  addStatistics(json, "ate_sim3", "_m", metrics.ateSim3_m);
  json["sim3_scale"] = metrics.sim3.scale;
  json["rpe_delta_frames"] = metrics.options.rpeDeltaFrames;
  json["rpe_all_pairs"] = metrics.options.rpeAllPairs;
  json["rpe_pairs"] = metrics.rpeTranslation_m.count;
  addStatistics(json, "rpe_trans", "_m", metrics.rpeTranslation_m);
  addStatistics(json, "rpe_rot", "_deg", metrics.rpeRotation_rad, kDegreesPerRadian);
  json["rpe_delta_m"] = metrics.options.rpeDelta_m;
  json["rpe_distance_pairs"] = metrics.rpeDistanceTranslation_m.count;
  addStatistics(json, "rpe_distance_trans", "_m", metrics.rpeDistanceTranslation_m);
  addStatistics(json, "rpe_distance_rot", "_deg", metrics.rpeDistanceRotation_rad, kDegreesPerRadian);
  json["drift_percent"] = numberOrNull(metrics.drift.translation_percent);
  json["drift_deg_per_100m"] = numberOrNull(metrics.drift.rotation_deg_per_100m);
  json["drift_segments"] = metrics.drift.segments;
  nlohmann::json lengths = nlohmann::json::array(), perLength = nlohmann::json::array();
  for (const DriftAtLength& d : metrics.drift.perLength) {
    lengths.push_back(d.length_m);
    perLength.push_back({{"length_m", d.length_m},
                         {"segments", d.segments},
                         {"drift_percent", d.translation_percent},
                         {"drift_deg_per_100m", d.rotation_deg_per_100m}});
  }
  json["drift_lengths_m"] = lengths.empty() ? nlohmann::json() : lengths;
  json["drift_per_length"] = perLength;
  json["scale_error_percent"] = numberOrNull(metrics.scaleErrorPercent);
  json["path_length_error_percent"] = numberOrNull(metrics.pathLengthErrorPercent);
  json["final_position_error_m"] = metrics.finalPositionError_m;
  json["final_position_error_percent"] = numberOrNull(metrics.finalPositionErrorPercent);
  return json;
}

}  // namespace lrsvo
