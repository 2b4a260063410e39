#pragma once

#include <vector>

#include <Eigen/Core>

#include "sim/terrain.h"
#include "sim/texel_tiles.h"

namespace lrsvo {

// Where a camera ray meets the terrain's surface, and on what.
struct SurfaceHit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // world
  const Terrain::Tree* tree = nullptr;              // the crown hit, if any
  const Terrain::Building* building = nullptr;      // the building hit (roof or wall), if any
};

// What one image sees of each surface that a texture may cache
// (SurfaceView::regions()): the ground, and the tree crowns in view.
struct SurfaceRegions {
  std::vector<TexelRegion> ground, crowns;
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
  // grey() of `count` hits into `out`: the renderer shades a row at a time,
  // which a texture may do faster than one virtual call per pixel.
  virtual void greyRow(const SurfaceHit* hits, const float* footprints_m, int count, float* out) const {
    for (int i = 0; i < count; ++i) out[i] = grey(hits[i], footprints_m[i]);
  }
};

}  // namespace lrsvo
