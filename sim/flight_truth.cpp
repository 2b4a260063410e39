#include "lrsvo/sim/flight_truth.h"

#include <string>

#include "lrsvo/graph/error.h"

namespace lrsvo {

FlightTruth simulateFlightTruth(const FlightOptions& flight, const Terrain& terrain, const Rig& rig,
                                const DeformationOptions& deformation) {
  FlightTruth truth;
  for (const FlightPose& pose : simulateFlight(flight)) {
    const Eigen::Vector3d centre = pose.cameraFromWorld.inverse().translation();
    const double ground = terrain.height(centre.x(), centre.y());
    if (!(centre.z() > ground))
      throw Error("flight: at t = " + std::to_string(pose.time_s) +
                  " s the aircraft (z = " + std::to_string(centre.z()) +
                  " m) is not above the terrain (z = " + std::to_string(ground) + " m); raise flight.altitude_m");
    truth.times_s.push_back(pose.time_s);
    truth.cameraFromWorld.push_back(pose.cameraFromWorld);
  }
  truth.extrinsics.resize(truth.times_s.size());
  for (int k = 1; k <= rig.secondaryCount(); ++k) {
    const auto perFrame = simulateDeformation(rig.extrinsics[k - 1], truth.times_s, deformation, k);
    for (std::size_t i = 0; i < perFrame.size(); ++i) truth.extrinsics[i].push_back(perFrame[i]);
  }
  return truth;
}

Eigen::Isometry3d trueCameraFromWorld(const FlightTruth& truth, int frame, int camera) {
  if (frame < 0 || frame >= static_cast<int>(truth.cameraFromWorld.size()))
    throw Error("flight truth: frame " + std::to_string(frame) + " outside the flight's " +
                std::to_string(truth.cameraFromWorld.size()) + " frames");
  if (camera < 0 || camera > static_cast<int>(truth.extrinsics[frame].size()))
    throw Error("flight truth: camera " + std::to_string(camera) + " not in the rig");
  const Eigen::Isometry3d& base = truth.cameraFromWorld[frame];
  return camera == 0 ? base : secondaryFromBase(truth.extrinsics[frame][camera - 1]) * base;
}

}  // namespace lrsvo
