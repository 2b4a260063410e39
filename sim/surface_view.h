#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/sim/surface_texture.h"
#include "lrsvo/sim/terrain.h"
#include "lrsvo/sim/texel_tiles.h"

namespace lrsvo {

// One camera's view of the terrain from one pose: where the ray through each
// pixel first meets the surface of Terrain::height (ground, tree crown or
// building). Trees and buildings are intersected exactly (ellipsoid, box);
// the rolling ground by Newton's method on a grid of pixels every
// kGroundGrid_px, between which the ray depth is interpolated bilinearly (the
// ground's wavelengths are hundreds of metres: the interpolation error is
// below a millimetre). Pixel centres lie at integer (u, v), OpenCV's convention.
// hit() traces one pixel; hitRow() a whole row at a fraction of the cost,
// which is how the renderer uses it.
class SurfaceView {
 public:
  static constexpr int kGroundGrid_px = 16;

  // Throws lrsvo::Error when a ray misses the ground (a camera below the
  // surface or seeing the horizon). The ground grid is solved in parallel
  // when threads > 1 (graph/parallel_for.h).
  SurfaceView(const Terrain& terrain, const Camera& camera, const Eigen::Isometry3d& cameraFromWorld, int threads = 1);

  // The surface point seen at pixel (u, v); its tree and building pointers
  // point into this view and live as long as it does.
  SurfaceHit hit(double u, double v) const;
  // The side of the patch of surface one pixel covers at a hit (metres),
  // widened where the ray meets the ground obliquely.
  double footprint(const SurfaceHit& hit) const;
  // hit(u, v) and footprint() for u = first .. first + count - 1 of row v
  // (inside the image), into row's pixels 0 .. count - 1, to rounding:
  // within a cell of the ground grid the ray and the ground depth are linear
  // in u, so they advance by a constant step. Only the footprint differs
  // more: its factor for the ray's direction is interpolated between the
  // nodes (5.6e-4 relative at most at a 417 px focal length; it falls
  // with the square of a cell's angle, so less at 1667 px). Each obstacle is tested over the pixels of its bounding box
  // alone.
  void hitRow(int v, int first, int count, RowHits& row) const;
  // The ground this view sees, one region per cell of the ground grid: the
  // box of its corners' ground points, widened by a footprint, and their
  // footprints, widened by 1 % (the surface curves a little between corners).
  // It holds what the ground hits of the cell's pixels sample.
  std::vector<TexelRegion> groundRegions() const;
  // One region per tree crown in view: the box of its crown, and the
  // footprints any point of the crown's bounding box can have from here.
  const std::vector<TexelRegion>& crownRegions() const { return crownRegions_; }
  SurfaceRegions regions() const { return {groundRegions(), crownRegions_, worldFromCameraRotation_.col(0).head<2>()}; }

 private:
  static constexpr int kTile_px = 32;  // obstacles are listed per square tile of the image

  // A tree crown as every ray from this view's centre meets it: the scale that makes its ellipsoid a unit
  // sphere, the centre in those coordinates (q0), and |q0|^2 - 1.
  struct CrownFromCentre {
    Eigen::Vector3d scale, q0;
    double c;
  };

  Eigen::Vector3d ray(double u, double v) const;  // world direction, unit depth along the optical axis
  double groundDepth(const Eigen::Vector3d& direction) const;
  void solveGroundGrid(int threads);
  double interpolatedGroundDepth(double u, double v) const;
  // The footprint of a hit at centre + toHit; proportional to |toHit|.
  double footprintAlong(const Eigen::Vector3d& toHit) const;
  // Whether the ray meets obstacle `id` (a tree as i, a building as -1 - i)
  // before `depth`; if so, makes `hit` that obstacle's hit and lowers depth to it.
  bool meets(int id, const Eigen::Vector3d& direction, double& depth, SurfaceHit& hit) const;
  void listObstacles(double bottom);
  // The footprints a hit anywhere in `box` can have, in a region over the box.
  TexelRegion regionOver(const Eigen::AlignedBox3d& box) const;
  // An obstacle and the pixels its bounding box may cover, inclusive.
  struct ObstacleSpan {
    int id;  // a tree as i, a building as -1 - i
    int u0, u1, v0, v1;
  };
  std::vector<ObstacleSpan>& tile(int tu, int tv) { return tiles_[tv * tilesU_ + tu]; }

  const Terrain& terrain_;
  Camera camera_;
  double meanFocal_;  // sqrt(fx fy), pixels
  Eigen::Matrix3d worldFromCameraRotation_;
  Eigen::Vector3d centre_;
  double groundBelowCentre_ = 0.0;  // where each ray's Newton solve starts: the ground's height below the centre
  Eigen::Isometry3d cameraFromWorld_;
  int nodesU_ = 0, nodesV_ = 0;
  std::vector<double> groundDepth_;        // [v node][u node]
  std::vector<double> footprintPerDepth_;  // [v node][u node]: footprintAlong() of the node's ray
  Terrain::Obstacles obstacles_;
  int tilesU_ = 0, tilesV_ = 0;
  std::vector<std::vector<ObstacleSpan>> tiles_;       // [tile]
  std::vector<CrownFromCentre> crownsFromCentre_;      // parallel to obstacles_.trees
  std::vector<std::array<double, 2>> buildingStarts_;  // the centre in each building's axes
  std::vector<TexelRegion> crownRegions_;
};

}  // namespace lrsvo
