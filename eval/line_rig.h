#pragma once

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/frontend/odometry/triangulation.h"

namespace lrsvo {

// Identical, parallel cameras with their centres on a line (a rectified rig,
// the set-up of the paper's Figs. 6 and 7): camera k sits at (centres_m[k], 0, 0)
// with its axes along the world's (x right, y down, z along the optical axis).
struct LineRig {
  PinholeIntrinsics intrinsics;
  std::vector<double> centres_m;

  // `cameras` cameras `spacing_m` apart, centred on the world origin.
  static LineRig evenlySpaced(const PinholeIntrinsics& intrinsics, int cameras, double spacing_m);

  int cameraCount() const { return static_cast<int>(centres_m.size()); }
  Eigen::Vector2d project(int camera, const Eigen::Vector3d& point) const;
  // The same rig and pixels as input to frontend's general triangulate().
  std::vector<TriangulationView> views(std::span<const Eigen::Vector2d> pixels) const;
};

// The least-squares (maximum-likelihood under isotropic pixel noise) point of
// one pixel per camera, in closed form. In this geometry every reprojection
// residual is linear in (X/Z, Y/Z, 1/Z): u_k = cx + fx (X/Z - x_k / Z) and
// v_k = cy + fy Y/Z, so the fit is a line through (x_k, u_k) whose slope gives
// the inverse depth. It is the minimiser frontend's triangulate() converges to.
// No point: the fitted inverse depth is not positive (zero or negative
// disparity), so no point in front of the cameras fits the pixels best.
std::optional<Eigen::Vector3d> triangulateOnLine(const LineRig& rig, std::span<const Eigen::Vector2d> pixels);

}  // namespace lrsvo
