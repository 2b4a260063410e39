#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/sim/flight.h"
#include "lrsvo/sim/rig_deformation.h"
#include "lrsvo/sim/terrain.h"

namespace lrsvo {

// A feature-level simulation: a flight over a terrain with a deforming rig,
// every scene point projected into every camera that sees it. No images.
// Each part has its own seed (terrain, flight, deformation); `seed` drives
// the scene points, pixel noise, outliers and dropped tracks, so trials over
// `seed` fly the same path over the same world with new features and noise.
struct FeatureSimulationOptions {
  FlightOptions flight;
  TerrainOptions terrain;
  Rig rig = paperRig();            // the calibration: what the estimator is told
  DeformationOptions deformation;  // applied to every secondary camera (each draws its own stream)
  int points = 4000;               // scene points over the flight's footprint (+ margin), if pointsPerFrame is 0
  int pointsPerFrame = 0;          // > 0: sample density so that a frame sees about this many points
  double pixelNoise_px = 1.0;      // Gaussian sigma per image coordinate
  double outlierFraction = 0.0;    // observations replaced by a uniform random pixel in the image
  double dropProbability = 0.0;    // per track and frame seen: the track ends (is lost) from that frame on
  double imageMargin_px = 0.0;     // visible: the true projection at least this far inside the image
  std::uint64_t seed = 1;
};

// The measurements and the ground truth. Track id = index into truePoints.
struct SimulatedSequence {
  Rig rig;                                                                  // the calibration (as told to estimators)
  std::vector<FrameObservations> frames;                                    // per kept frame; by track, then camera
  std::vector<Eigen::Isometry3d> trueCameraFromWorld;                       // [frame]: the base camera
  std::vector<std::vector<VertexStereoExtrinsic::Vector6>> trueExtrinsics;  // [frame][k - 1]: camera k's true s
  std::vector<Eigen::Vector3d> truePoints;                                  // [track]
  std::vector<std::vector<Eigen::Vector2d>> truePixels;  // [frame][observation]: the exact projection, no noise
  std::vector<std::vector<bool>> outlier;                // [frame][observation]: a uniform random pixel
};

// Visibility: a point is observed by camera k in a frame when it lies in
// front of the camera and its true projection (true pose, true extrinsic of
// that frame) lies inside the image by imageMargin_px; the measurement is that
// projection plus noise (or an outlier). Occlusion by the terrain is ignored.
// Throws lrsvo::Error on bad options, and when the aircraft is not above the
// terrain beneath it or a camera sees the horizon.
SimulatedSequence simulateSequence(const FeatureSimulationOptions& options);

// The true pose (camera-from-world) of camera k in a frame of the sequence.
Eigen::Isometry3d trueCameraPose(const SimulatedSequence& sequence, int frame, int camera);

}  // namespace lrsvo
