#include "lrsvo/sim/feature_simulator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/sim/flight_truth.h"
#include "lrsvo/sim/footprint.h"
#include "lrsvo/sim/scene_point_grid.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

// Independent streams, so that e.g. turning outliers on leaves the noise as it was.
constexpr std::uint64_t kPointStream = 1, kNoiseStream = 2, kOutlierStream = 3, kDropStream = 4;
constexpr double kMaxPoints = 5e7;  // a few GB of observations; far beyond any flight of the paper

void check(bool condition, const std::string& message) {
  if (!condition) throw Error("feature simulation: " + message);
}

void validate(const FeatureSimulationOptions& o) {
  o.rig.validate();
  check(o.points >= 0 && o.pointsPerFrame >= 0, "points and pointsPerFrame must be >= 0");
  check(std::isfinite(o.pixelNoise_px) && o.pixelNoise_px >= 0.0, "pixelNoise_px must be finite and >= 0");
  check(o.outlierFraction >= 0.0 && o.outlierFraction <= 1.0, "outlierFraction must lie in [0, 1]");
  check(o.dropProbability >= 0.0 && o.dropProbability <= 1.0, "dropProbability must lie in [0, 1]");
  for (const Camera& camera : o.rig.cameras)
    check(o.imageMargin_px >= 0.0 && 2.0 * o.imageMargin_px < std::min(camera.width, camera.height),
          "imageMargin_px must be >= 0 and leave part of every image");
}

class Simulator {
 public:
  explicit Simulator(const FeatureSimulationOptions& options)
      : o_(options),
        terrain_(options.terrain),
        noiseRng_(mixSeed(options.seed, kNoiseStream)),
        outlierRng_(mixSeed(options.seed, kOutlierStream)),
        dropRng_(mixSeed(options.seed, kDropStream)) {}

  SimulatedSequence run() {
    SimulatedSequence sequence;
    sequence.rig = o_.rig;
    simulateTruth(sequence);
    const ScenePointGrid grid = samplePoints(sequence);
    sequence.truePoints = grid.points();
    lost_.assign(sequence.truePoints.size(), false);
    for (std::size_t i = 0; i < sequence.trueCameraFromWorld.size(); ++i) observeFrame(sequence, grid, i);
    return sequence;
  }

 private:
  void simulateTruth(SimulatedSequence& sequence) {
    FlightTruth truth = simulateFlightTruth(o_.flight, terrain_, o_.rig, o_.deformation);
    for (double time : truth.times_s) sequence.frames.push_back({time, {}});
    sequence.trueCameraFromWorld = std::move(truth.cameraFromWorld);
    sequence.trueExtrinsics = std::move(truth.extrinsics);
  }

  // Every frame's search box: the ground footprints of all its cameras on the
  // lowest possible terrain (any visible point lies between a camera centre
  // and that footprint). The points are spread over the cells these boxes
  // touch, at the density that puts pointsPerFrame in a base-camera footprint.
  ScenePointGrid samplePoints(const SimulatedSequence& sequence) {
    double footprintArea = 0.0;
    for (std::size_t i = 0; i < sequence.trueCameraFromWorld.size(); ++i) {
      Eigen::AlignedBox2d box;
      for (int k = 0; k < static_cast<int>(o_.rig.cameras.size()); ++k) {
        const Eigen::Isometry3d pose = trueCameraPose(sequence, static_cast<int>(i), k);
        box.extend(pose.inverse().translation().head<2>());
        for (const Eigen::Vector2d& corner : groundFootprint(o_.rig.cameras[k], pose, terrain_.minHeight()))
          box.extend(corner);
      }
      searchBoxes_.push_back(box);
      const Eigen::Vector3d centre = sequence.trueCameraFromWorld[i].inverse().translation();
      footprintArea += polygonArea(groundFootprint(o_.rig.cameras[0], sequence.trueCameraFromWorld[i],
                                                   terrain_.groundHeight(centre.x(), centre.y())));
    }
    footprintArea /= static_cast<double>(searchBoxes_.size());
    ScenePointGrid grid(searchBoxes_, 0.5 * std::sqrt(footprintArea));
    const double count =
        o_.pointsPerFrame > 0 ? std::round(o_.pointsPerFrame * grid.area() / footprintArea) : o_.points;
    check(count <= kMaxPoints, "pointsPerFrame " + std::to_string(o_.pointsPerFrame) + " over this flight needs " +
                                   std::to_string(count) + " points, more than the " + std::to_string(kMaxPoints) +
                                   " allowed; lower pointsPerFrame or shorten the flight");
    grid.sample(terrain_, static_cast<int>(count), mixSeed(o_.seed, kPointStream));
    return grid;
  }

  void observeFrame(SimulatedSequence& sequence, const ScenePointGrid& grid, std::size_t frame) {
    std::vector<Eigen::Isometry3d> poses;
    for (int k = 0; k < static_cast<int>(o_.rig.cameras.size()); ++k)
      poses.push_back(trueCameraPose(sequence, static_cast<int>(frame), k));
    std::vector<Observation>& observations = sequence.frames[frame].observations;
    std::vector<Eigen::Vector2d>& truePixels = sequence.truePixels.emplace_back();
    std::vector<bool>& outliers = sequence.outlier.emplace_back();
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int track : grid.pointsNear(searchBoxes_[frame])) {
      if (lost_[track]) continue;
      std::vector<Observation> seen;
      for (int k = 0; k < static_cast<int>(poses.size()); ++k) {
        const Eigen::Vector3d inCamera = poses[k] * sequence.truePoints[track];
        if (inCamera.z() <= 0.0) continue;
        const Eigen::Vector2d pixel = o_.rig.cameras[k].intrinsics.project(inCamera);
        if (o_.rig.cameras[k].inImage(pixel, o_.imageMargin_px)) seen.push_back({track, k, pixel});
      }
      if (seen.empty()) continue;
      if (unit(dropRng_) < o_.dropProbability) {
        lost_[track] = true;
        continue;
      }
      for (Observation& observation : seen) {
        truePixels.push_back(observation.pixel);
        const Eigen::Vector2d noise = o_.pixelNoise_px * Eigen::Vector2d(normal(noiseRng_), normal(noiseRng_));
        const Camera& camera = o_.rig.cameras[observation.camera];
        const bool isOutlier = unit(outlierRng_) < o_.outlierFraction;
        const Eigen::Vector2d randomPixel(camera.width * unit(outlierRng_), camera.height * unit(outlierRng_));
        observation.pixel = isOutlier ? randomPixel : Eigen::Vector2d(observation.pixel + noise);
        outliers.push_back(isOutlier);
        observations.push_back(observation);
      }
    }
  }

  const FeatureSimulationOptions& o_;
  Terrain terrain_;
  std::mt19937_64 noiseRng_, outlierRng_, dropRng_;
  std::vector<Eigen::AlignedBox2d> searchBoxes_;  // [frame]
  std::vector<bool> lost_;                        // [track]: dropped for good
};

}  // namespace

SimulatedSequence simulateSequence(const FeatureSimulationOptions& options) {
  validate(options);
  return Simulator(options).run();
}

Eigen::Isometry3d trueCameraPose(const SimulatedSequence& sequence, int frame, int camera) {
  check(frame >= 0 && frame < static_cast<int>(sequence.trueCameraFromWorld.size()),
        "frame " + std::to_string(frame) + " outside the sequence");
  check(camera >= 0 && camera < static_cast<int>(sequence.rig.cameras.size()),
        "camera " + std::to_string(camera) + " not in the rig");
  const Eigen::Isometry3d& base = sequence.trueCameraFromWorld[frame];
  return camera == 0 ? base : secondaryFromBase(sequence.trueExtrinsics[frame][camera - 1]) * base;
}

}  // namespace lrsvo
