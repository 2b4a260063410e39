#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/constraints/bounds.h"
#include "lrsvo/edges/pinhole.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_scale.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// A seeded stereo sliding window like the VO's (docs/method.md): a base camera
// looking straight down at mildly hilly terrain from an aircraft flying along
// world x (world z up; camera x along the flight, camera z down), a secondary
// camera `baseline_m` further along the flight, every point tracked over
// consecutive frames and seen by both cameras in each.
struct WindowProblemOptions {
  using Vector6 = VertexStereoExtrinsic::Vector6;

  int frames = 15;
  int points = 500;
  double altitude_m = 100.0;    // above the terrain's mean height
  double frameSpacing_m = 2.0;  // flight distance between keyframes (speed x keyframe interval)
  double baseline_m = 0.7;      // secondary centre along the base camera's x axis (the flight direction)
  int imageWidth = 1280;
  int imageHeight = 960;
  double horizontalFov_deg = 42.0;  // focal = (width / 2) / tan(fov / 2), ~1667 px; square pixels
  double pixelNoise = 1.0;          // sigma of the noise added to the simulated measurements (0: exact)
  double measurementSigma = 1.0;    // the model's: information = I / sigma^2 (docs/method.md: 1 px^2)
  int minTrackLength = 5;           // frames per point, drawn uniformly, capped by what the footprint allows
  int maxTrackLength = 15;
  double terrainRelief_m = 5.0;      // peak height of the terrain above (and below) its mean
  double attitudeJitter_rad = 0.01;  // sigma of the aircraft's roll, pitch and yaw about level flight
  double heightJitter_m = 1.0;       // sigma of the flight height about altitude_m
  double imageMargin_px = 10.0;      // every true projection this far inside the image

  // The true extrinsic is calibration + deformation; the start is calibration.
  // Calibration: the secondary centre at (baseline_m, 0, 0), no rotation.
  Vector6 deformation = (Vector6() << 3e-4, -2e-4, 4e-4, 3e-3, -2e-3, 4e-3).finished();
  // Overrides the deformation's roll and yaw with 1.5 times their tolerance
  // (roll up, yaw down), so the optimum lies outside the box and those bounds are active.
  bool trueOutsideBounds = false;
  // Box around the calibration: +- on x, y, z (m) and roll, pitch, yaw (rad).
  double positionTolerance_m = 1e-3;
  double angleTolerance_rad = 0.01;

  // Start perturbation of the non-fixed poses and of every point, per axis.
  double poseNoise_m = 0.05;
  double poseNoise_rad = 0.002;
  double pointNoise_m = 0.5;

  // Initialisation window (docs/method.md, long-range initialisation): the map (all
  // positions) is multiplied by startScale; with withScale a kappa vertex
  // (start 1, truth 1 / startScale) joins every secondary edge.
  bool withScale = false;
  double startScale = 1.0;
  // The first poses are held at their (scaled) truth to fix the gauge; at
  // least two when withScale, as the map's unit is then free. With one, the
  // map's scale and the extrinsic centre c still share a gauge freedom
  // (scaling both changes no projection) that only c's bounds limit.
  int fixedPoses = 1;

  std::string robustKernel;  // "" for none, else a registered kernel name
  double robustKernelDelta = 2.0;
  std::uint64_t seed = 1;
};

struct WindowProblem {
  Graph graph;
  std::vector<VertexPose*> poses;
  std::vector<VertexPoint3*> points;
  VertexStereoExtrinsic* extrinsic = nullptr;
  VertexScale* scale = nullptr;  // withScale only
  Bounds extrinsicBounds;        // the six extrinsic parameters, calibration +- tolerance
  PinholeIntrinsics intrinsics;  // both cameras

  // Ground truth in metres (before startScale).
  std::vector<Eigen::Isometry3d> truePoses;  // camera-from-world
  std::vector<Eigen::Vector3d> truePoints;
  VertexStereoExtrinsic::Vector6 calibratedExtrinsic;
  VertexStereoExtrinsic::Vector6 trueExtrinsic;
  double trueKappa = 1.0;  // 1 / startScale
};

// Builds the problem; the same options (seed included) give the same problem.
// Vertex ids: poses 0..frames-1, the extrinsic, kappa (withScale), then the
// points. Throws lrsvo::Error on options that cannot make a valid window
// (e.g. a footprint too small for the shortest track).
WindowProblem makeWindowProblem(const WindowProblemOptions& options);

// The map's scale in the true unit: the estimated over the true distance
// between the first and last camera centres.
double estimatedMapScale(const WindowProblem& problem);

}  // namespace lrsvo
