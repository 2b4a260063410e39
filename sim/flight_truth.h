#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/sim/flight.h"
#include "lrsvo/sim/rig_deformation.h"
#include "lrsvo/sim/terrain.h"

namespace lrsvo {

// The true motion of a simulated rig: the flight's base-camera poses and,
// per frame, every secondary camera's deformed extrinsic. Shared by the
// feature-level simulator and the image renderer.
struct FlightTruth {
  std::vector<double> times_s;                                          // [frame]
  std::vector<Eigen::Isometry3d> cameraFromWorld;                       // [frame]: the base camera
  std::vector<std::vector<VertexStereoExtrinsic::Vector6>> extrinsics;  // [frame][k - 1]: camera k's true s
};

// Flies `flight`, deforms every secondary camera of `rig` from its
// calibration with `deformation` (each camera its own stream). Throws
// lrsvo::Error when the aircraft is not above the terrain beneath it in
// some frame (the message names the time and heights).
FlightTruth simulateFlightTruth(const FlightOptions& flight, const Terrain& terrain, const Rig& rig,
                                const DeformationOptions& deformation);

// Camera k's true pose (camera-from-world) in a frame.
Eigen::Isometry3d trueCameraFromWorld(const FlightTruth& truth, int frame, int camera);

}  // namespace lrsvo
