#include "lrsvo/eval/initialization_trial.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "lrsvo/eval/paper_cameras.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

constexpr double kFrameRate_hz = 30.0;
constexpr std::uint64_t kFlexStream = 0x666c6578;  // "flex": the rig's static offset from calibration

Eigen::Vector3d centre(const Eigen::Isometry3d& cameraFromWorld) { return cameraFromWorld.inverse().translation(); }

}  // namespace

double paperSpeedForAltitude(double altitude_m) {
  const double fraction = std::clamp((altitude_m - 10.0) / 90.0, 0.0, 1.0);
  return 15.0 + fraction * 35.0;
}

FeatureSimulationOptions initializationSimulation(const InitializationFlight& flight) {
  if (flight.frames < 3) throw Error("initialisation flight: needs at least 3 frames");
  if (!(flight.altitude_m > 0.0) || !(flight.speed_m_s > 0.0) || !(flight.distance_m > 0.0))
    throw Error("initialisation flight: altitude, speed and distance must be positive");
  FeatureSimulationOptions options;
  const double focal = paperOpticsFocal_px();
  options.rig = paperRig(0.7, kPaperImageWidth, kPaperImageHeight, 2.0 * std::atan(0.5 * kPaperImageWidth / focal));

  const double alongTrackFootprint_m = flight.altitude_m * kPaperImageWidth / focal;
  const double wantedSpacing_m =
      std::min(flight.distance_m / (flight.frames - 1), flight.maxFootprintStep * alongTrackFootprint_m);
  const double perFrame_m = flight.speed_m_s / kFrameRate_hz;
  options.flight.frameStep = std::max(1, static_cast<int>(std::lround(wantedSpacing_m / perFrame_m)));
  const double spacing_m = options.flight.frameStep * perFrame_m;
  options.flight.altitude_m = flight.altitude_m;
  options.flight.speed_m_s = flight.speed_m_s;
  options.flight.frameRate_hz = kFrameRate_hz;
  // Half a spacing beyond the last frame, so rounding never loses it.
  options.flight.legs = {{FlightLeg::Kind::Straight, (flight.frames - 0.5) * spacing_m}};
  options.flight.seed = flight.seed;

  // Farmland like the paper's flight area: gentle relief, no trees or
  // buildings, which at 10-20 m would reach the aircraft.
  options.terrain.relief_m = std::min(4.0, 0.1 * flight.altitude_m);
  options.terrain.treeDensity_per_km2 = 0.0;
  options.terrain.buildingDensity_per_km2 = 0.0;
  options.terrain.seed = flight.seed;
  options.deformation.seed = flight.seed;
  options.deformation.drift.setZero();
  std::mt19937_64 rng(mixSeed(flight.seed, kFlexStream));
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int i = 0; i < 6; ++i)
    options.deformation.offset[i] = flight.flexFraction * options.rig.tolerance[i] * uniform(rng);
  options.pointsPerFrame = flight.pointsPerFrame;
  options.pixelNoise_px = flight.pixelNoise_px;
  options.seed = flight.seed;
  return options;
}

InitializationScore scoreInitialization(const SimulatedSequence& sequence, int frames,
                                        const InitializationResult& result) {
  if (static_cast<int>(sequence.trueCameraFromWorld.size()) < frames)
    throw Error("scoreInitialization: the sequence has fewer frames than the initialisation used");
  const std::vector<Eigen::Isometry3d> truth =
      alignToFirstCamera({sequence.trueCameraFromWorld.begin(), sequence.trueCameraFromWorld.begin() + frames});
  InitializationScore score;
  score.success = result.success;
  score.failure = result.failure;
  score.distanceFlown_m = (centre(truth.back()) - centre(truth.front())).norm();
  const int reached = static_cast<int>(result.cameraFromWorld.size());
  score.reachedEnd = reached >= frames;
  score.rawFinalPositionError_m = score.reachedEnd
                                      ? (centre(result.cameraFromWorld[frames - 1]) - centre(truth.back())).norm()
                                      : std::numeric_limits<double>::quiet_NaN();
  score.finalPositionError_m = score.reachedEnd && score.success
                                   ? std::min(score.rawFinalPositionError_m, score.distanceFlown_m)
                                   : score.distanceFlown_m;
  score.scaleRatio = std::numeric_limits<double>::quiet_NaN();
  if (reached >= 2) {
    const double estimated = (centre(result.cameraFromWorld[reached - 1]) - centre(result.cameraFromWorld[0])).norm();
    const double trueDistance = (centre(truth[reached - 1]) - centre(truth[0])).norm();
    if (estimated > 0.0) score.scaleRatio = trueDistance / estimated;
  }
  return score;
}

}  // namespace lrsvo
