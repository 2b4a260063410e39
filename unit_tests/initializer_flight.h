#pragma once

#include <cstdint>

#include "lrsvo/frontend/odometry/initialization_result.h"
#include "lrsvo/sim/feature_simulator.h"

namespace lrsvo::test {

// The paper's initialisation flight (Section 4.3.1): 60 m straight and level
// at 20 m/s, 10 frames (every 10th of 30 Hz, 6.7 m apart), paperRig()
// (1280x960, 42 deg, 0.7 m), 1 px noise, about 300 features per frame, no
// outliers. The rig is deformed by a constant offset
// within the +-1 mm / +-10 mrad bounds, `deformation` times
// (0.5, -0.4, 0.3) mm and (-3, 4, 5) mrad (pitch 4 mrad = 6.7 px at f = 1667
// px, the paper's "0.2 deg -> ~3 px" regime), plus the simulator's default
// per-frame vibration (0.2 mrad); no slow drift, since one shared S is what
// the initialiser estimates over its 3 s.
inline FeatureSimulationOptions initializationFlightOptions(double altitude_m, std::uint64_t seed,
                                                            double deformation = 1.0) {
  FeatureSimulationOptions options;
  options.flight.altitude_m = altitude_m;
  options.flight.speed_m_s = 20.0;
  options.flight.frameRate_hz = 30.0;
  options.flight.frameStep = 10;
  options.flight.legs = {{FlightLeg::Kind::Straight, 60.0}};
  options.flight.seed = seed;
  options.pointsPerFrame = 300;
  options.pixelNoise_px = 1.0;
  options.deformation.drift.setZero();
  options.deformation.offset << 5e-4, -4e-4, 3e-4, -3e-3, 4e-3, 5e-3;
  options.deformation.offset *= deformation;
  options.deformation.seed = seed;
  options.seed = seed;
  return options;
}

// That flight, simulated.
inline SimulatedSequence initializationFlight(double altitude_m, std::uint64_t seed, double deformation = 1.0) {
  return simulateSequence(initializationFlightOptions(altitude_m, seed, deformation));
}

// Distance between the final camera's estimated and true centres, with the
// truth expressed in the first camera's frame (the result's world).
inline double finalPositionError(const InitializationResult& result, const SimulatedSequence& sequence) {
  const std::vector<Eigen::Isometry3d> truth = alignToFirstCamera(sequence.trueCameraFromWorld);
  const std::size_t last = result.cameraFromWorld.size() - 1;
  return (result.cameraFromWorld[last].inverse().translation() - truth[last].inverse().translation()).norm();
}

// Distance between the first and final true camera centres.
inline double distanceFlown(const SimulatedSequence& sequence, std::size_t frames) {
  return (sequence.trueCameraFromWorld[frames - 1].inverse().translation() -
          sequence.trueCameraFromWorld.front().inverse().translation())
      .norm();
}

}  // namespace lrsvo::test
