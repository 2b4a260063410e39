#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lrsvo/sim/surface_texture.h"
#include "lrsvo/sim/texel_tiles.h"

namespace lrsvo {

struct TextureMemo;      // ground_texture.cpp: what the texture reuses from one texel to the next
struct FieldCellLayout;  // ground_texture.cpp: the hashes that lay out one cell of the field grid

// Rural farmland seen from above, as grey levels: a grid of fields (rotated
// by a seeded angle), each cell split in two; each field ploughed, in crop
// rows or pasture, with its own brightness and row direction and spacing.
// Field edges carry a track (bright, with darker ruts), a hedge (dark, leafy)
// or a thin grass verge. Tree crowns are dark and leafy, shaded towards the
// rim; roofs bright and flat with faint corrugation. Every surface has grain
// from 2 cm to tens of metres, so that corner detectors find well-localised
// features at any altitude from 30 m (~2 cm per pixel) to 120 m (~7 cm).
struct GroundTextureOptions {
  double fieldSize_m = 120.0;      // side of a grid cell (two fields)
  double trackProbability = 0.25;  // per cell edge: a track
  double hedgeProbability = 0.45;  // per cell edge or split line: a hedge (otherwise a verge)
  double grainContrast = 0.35;     // relative amplitude of the fine grain (2 cm - 1 m)
  std::uint64_t seed = 1;
};

class GroundTexture : public SurfaceTexture {
 public:
  // Throws lrsvo::Error on a non-positive field size, probabilities outside
  // [0, 1] (or summing above 1) or a negative grain contrast.
  explicit GroundTexture(const GroundTextureOptions& options);
  GroundTexture(const GroundTexture&) = delete;  // its texel cache calls back into it
  GroundTexture& operator=(const GroundTexture&) = delete;

  // Caches the texels of the ground and the crowns an image sees (sim/texel_tiles.h).
  void prepare(const SurfaceRegions& seen, int threads) const override;
  // Ground and crown hits from the caches filled by prepare() (or directly,
  // to the same value, outside them); roofs and walls directly.
  float grey(const SurfaceHit& hit, double footprint_m) const override;
  void greyRow(const RowHits& row, float* out) const override;
  // The ground alone (fields, tracks, hedges) at (x, y), evaluated directly.
  float ground(double x, double y, double footprint_m) const;

 private:
  // The layout of field cell (i, j), from the memo when the memo holds it.
  const FieldCellLayout& fieldCell(std::int64_t i, std::int64_t j, TextureMemo& memo) const;
  // One field's grey at (u, v), from its four hashes: kind, shade, row direction, row spacing.
  float field(double u, double v, const std::array<double, 4>& hashes, double footprint_m, TextureMemo& memo) const;
  float tree(const SurfaceHit& hit, double footprint_m) const;
  // A crown's tone (its own grey, by a hash of its position), and that tone shaded towards the rim at a hit on
  // it; tree() is the shade times crownDetail(), clamped.
  double crownTone(const Terrain::Tree& tree) const;
  double crownShade(const SurfaceHit& hit, double tone) const;
  // A crown's grey from its shade and its detail (the one formula of tree() and greyRow()).
  static float crownGrey(double shade, float detail);
  // The leafy clumps of every crown, a texture of x and y (cached in crownTexels_).
  float crownDetail(double x, double y, double footprint_m) const;
  float building(const SurfaceHit& hit, double footprint_m) const;
  // ground() with its broad tone and grain noise given (what it sums of those layers at x, y).
  float groundAt(double x, double y, double footprint_m, double broad, double grain, TextureMemo& memo) const;
  // ground() and crownDetail() along a row of texels (TexelTiles::RowFunction).
  void groundRow(std::int64_t ix, std::int64_t iy, double texel_m, int count, float* out) const;
  void crownDetailRow(std::int64_t ix, std::int64_t iy, double texel_m, int count, float* out) const;

  GroundTextureOptions options_;
  std::uint32_t salt_;
  double cosGrid_, sinGrid_;  // the field grid's rotation
  mutable TexelTiles groundTexels_, crownTexels_;
};

}  // namespace lrsvo
