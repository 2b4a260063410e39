#pragma once

#include <cstdint>
#include <string>

#include "lrsvo/frontend/odometry/initialization_result.h"
#include "lrsvo/sim/feature_simulator.h"

namespace lrsvo {

// The simulated flight of the paper's initialisation experiments (Section
// 4.3.1): a 0.7 m rig of 1024x768 cameras (6 mm lens, 1/3" sensor) flown
// straight over farmland, 10 frames spread over about 60 m, 1 px noise, no
// wrong matches, a rig deforming within its bounds.
struct InitializationFlight {
  double altitude_m = 100.0;
  double speed_m_s = 30.0;
  int frames = 10;
  double distance_m = 60.0;  // flown between the first and the last frame, at most
  // The frames are at most this fraction of the along-track footprint apart,
  // so that a track spans about four frames even at low altitude (the
  // monocular start needs three); there the distance flown is shorter than
  // distance_m (at 10 m, 18 m; from 34 m up, 60 m).
  double maxFootprintStep = 0.25;
  // The rig has flexed since its calibration by a constant amount drawn
  // uniformly within this fraction of its tolerances (1 mm, 0.01 rad), plus
  // the simulator's per-frame vibration; no slow drift within the 1-4 s flown.
  double flexFraction = 0.5;
  int pointsPerFrame = 200;  // about equal at every altitude, as in the paper
  double pixelNoise_px = 1.0;
  std::uint64_t seed = 1;
};

// Speed rising linearly from 15 m/s at 10 m to 50 m/s at 100 m (the paper's
// 15-50 m/s "to ensure image overlap"), 50 m/s above.
double paperSpeedForAltitude(double altitude_m);

// The simulator's settings for such a flight: frames 30 Hz apart in time, one
// kept every frameStep so that kept frames are spacing_m apart.
FeatureSimulationOptions initializationSimulation(const InitializationFlight& flight);

// How an initialisation ended against the truth: the final camera's position
// error and the scale error as the ratio of true to estimated distance
// between the first and the last camera reached. As in the paper's Fig. 17,
// the error is limited to the distance flown ("the limit of the length of the
// data set"): a run that failed (by its own verdict) or did not reach the last
// frame scores that limit; the unlimited error is kept beside it.
struct InitializationScore {
  bool success = false;     // the initialiser's own verdict
  bool reachedEnd = false;  // it returned a pose for every frame
  std::string failure;
  double distanceFlown_m = 0.0;
  double finalPositionError_m = 0.0;     // limited to distanceFlown_m
  double rawFinalPositionError_m = 0.0;  // of the last pose returned (NaN when none)
  double scaleRatio = 0.0;               // true / estimated distance (NaN without two poses)
};

InitializationScore scoreInitialization(const SimulatedSequence& sequence, int frames,
                                        const InitializationResult& result);

}  // namespace lrsvo
