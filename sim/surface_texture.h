#pragma once

#include <vector>

#include <Eigen/Core>

#include "lrsvo/sim/terrain.h"
#include "lrsvo/sim/texel_tiles.h"

namespace lrsvo {

// Where a camera ray meets the terrain's surface, and on what.
struct SurfaceHit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // world
  const Terrain::Tree* tree = nullptr;              // the crown hit, if any
  const Terrain::Building* building = nullptr;      // the building hit (roof or wall), if any
};

// What a row of pixels sees (SurfaceView::hitRow()), kept apart by surface:
// the ground, where every pixel's ray meets it, in arrays the texture samples
// in one pass; and the pixels whose ray meets a tree crown or a building
// first, with that hit.
struct RowHits {
  struct Obstacle {
    int pixel;
    SurfaceHit hit;
    float footprint_m;
  };
  std::vector<double> x, y, z;      // per pixel: the ground hit (world)
  std::vector<float> footprint_m;   // per pixel: its footprint on the ground
  std::vector<Obstacle> obstacles;  // the pixels whose ray meets an obstacle before the ground
  std::vector<int> obstacleAt;      // per pixel: its entry in obstacles, or -1

  int size() const { return static_cast<int>(x.size()); }
  // Sized for `count` pixels, no obstacle hits yet.
  void reset(int count);
  // What pixel i sees, and the footprint there.
  SurfaceHit hit(int i) const;
  float footprintAt(int i) const;
};

inline void RowHits::reset(int count) {
  x.resize(count), y.resize(count), z.resize(count), footprint_m.resize(count);
  obstacleAt.assign(count, -1);
  obstacles.clear();
}

inline SurfaceHit RowHits::hit(int i) const {
  const int k = obstacleAt[i];
  return k < 0 ? SurfaceHit{Eigen::Vector3d(x[i], y[i], z[i]), nullptr, nullptr} : obstacles[k].hit;
}

inline float RowHits::footprintAt(int i) const {
  const int k = obstacleAt[i];
  return k < 0 ? footprint_m[i] : obstacles[k].footprint_m;
}

// What one image sees of each surface that a texture may cache
// (SurfaceView::regions()): the ground, and the tree crowns in view.
struct SurfaceRegions {
  std::vector<TexelRegion> ground, crowns;
  Eigen::Vector2d rowDirection = Eigen::Vector2d::UnitX();  // world (x, y) along which the image's rows run
};

// The grey level (albedo, 0..255) of the surface at a hit, averaged over a
// patch `footprint_m` across (one pixel's footprint), so that detail finer
// than a pixel averages out instead of aliasing.
class SurfaceTexture {
 public:
  virtual ~SurfaceTexture() = default;
  // Called once before the grey() calls of one image, with what it sees
  // (SurfaceView::regions()): a texture may fill its caches here
  // (on up to `threads` threads). grey() may then run on many threads at
  // once; prepare() must not run while another image of the same texture is
  // being shaded.
  virtual void prepare(const SurfaceRegions& seen, int threads) const { (void)seen, (void)threads; }
  virtual float grey(const SurfaceHit& hit, double footprint_m) const = 0;
  // grey() of every pixel of a row into out[0 .. row.size() - 1]: the
  // renderer shades a row at a time, which a texture may do faster than one
  // virtual call per pixel.
  virtual void greyRow(const RowHits& row, float* out) const {
    for (int i = 0; i < row.size(); ++i) out[i] = grey(row.hit(i), row.footprintAt(i));
  }
};

}  // namespace lrsvo
