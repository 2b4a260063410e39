#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/edges/pinhole.h"

namespace lrsvo {

// One observation of a point: the camera's pose (camera-from-world), its
// intrinsics and the measured pixel.
struct TriangulationView {
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
  PinholeIntrinsics intrinsics;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

struct TriangulationOptions {
  int maxIterations = 10;              // Gauss-Newton refinement of the linear solution
  double minParallax_rad = 0.0;        // largest angle between any two rays must exceed this
  double maxReprojectionError_px = 0;  // > 0: reject when the RMS reprojection error is larger
};

struct TriangulationResult {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // world frame
  bool valid = false;                               // in front of every camera, enough parallax, within the error limit
  double rmsReprojectionError_px = 0.0;
  double parallax_rad = 0.0;  // largest angle between two of the rays
};

// The linear (DLT) solution: the smallest right singular vector of the stacked
// x P3 - P1, y P3 - P2 rows, in normalised image coordinates. Needs >= 2 views.
Eigen::Vector3d triangulateLinear(const std::vector<TriangulationView>& views);

// DLT, then Gauss-Newton on the reprojection error over every view (the
// maximum-likelihood point under isotropic pixel noise). Throws lrsvo::Error
// with fewer than two views.
TriangulationResult triangulate(const std::vector<TriangulationView>& views, const TriangulationOptions& options = {});

}  // namespace lrsvo
