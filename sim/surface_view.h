#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "frontend/rig.h"
#include "sim/surface_texture.h"
#include "sim/terrain.h"

namespace lrsvo {

// One camera's view of the terrain from one pose: where the ray through each
// pixel first meets the surface of Terrain::height (ground, tree crown or
// building). Trees and buildings are intersected exactly (ellipsoid, box);
// the rolling ground by Newton's method on a grid of pixels every
// kGroundGrid_px, between which the ray depth is interpolated bilinearly (the
// ground's wavelengths are hundreds of metres: the interpolation error is
// below a millimetre). Pixel centres lie at integer (u, v), OpenCV's convention.
class SurfaceView {
 public:
  static constexpr int kGroundGrid_px = 16;

  // Throws lrsvo::Error when a ray misses the ground (a camera below the
  // surface or seeing the horizon).
  SurfaceView(const Terrain& terrain, const Camera& camera, const Eigen::Isometry3d& cameraFromWorld);

  // The surface point seen at pixel (u, v); its tree and building pointers
  // point into this view and live as long as it does.
  SurfaceHit hit(double u, double v) const;
  // The side of the patch of surface one pixel covers at a hit (metres),
  // widened where the ray meets the ground obliquely.
  double footprint(const SurfaceHit& hit) const;

 private:
  static constexpr int kTile_px = 32;  // obstacles are listed per square tile of the image

  Eigen::Vector3d ray(double u, double v) const;  // world direction, unit depth along the optical axis
  double groundDepth(const Eigen::Vector3d& direction) const;
  double interpolatedGroundDepth(double u, double v) const;
  void listObstacles(double bottom);
  std::vector<int>& tile(int tu, int tv) { return tiles_[tv * tilesU_ + tu]; }

  const Terrain& terrain_;
  Camera camera_;
  double meanFocal_;  // sqrt(fx fy), pixels
  Eigen::Matrix3d worldFromCameraRotation_;
  Eigen::Vector3d centre_;
  Eigen::Isometry3d cameraFromWorld_;
  int nodesU_ = 0, nodesV_ = 0;
  std::vector<double> groundDepth_;  // [v node][u node]
  Terrain::Obstacles obstacles_;
  int tilesU_ = 0, tilesV_ = 0;
  std::vector<std::vector<int>> tiles_;  // [tile]: trees as i, buildings as -1 - i
};

}  // namespace lrsvo
