#include "lrsvo/sim/ground_texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/sim/inline_math.h"
#include "lrsvo/sim/value_noise.h"

namespace lrsvo {

// The hashes that lay out one cell of the field grid: its split line, its two fields and the four edges
// around it. Every texel of the cell reads the same ones.
struct FieldCellLayout {
  bool filled = false;
  std::int64_t i = 0, j = 0;
  double splitAcrossU = 0.0, splitAt = 0.0, splitHedge = 0.0;
  std::array<std::array<double, 4>, 2> fields{};     // per half: kind, shade, row direction, row spacing
  std::array<std::array<double, 2>, 2> edgeKinds{};  // per axis (u, v): the edge at the cell's start, at its end
  std::array<std::array<double, 2>, 2> trackTones{};
};

// What the ground texture reuses on this thread: the noise's lattice cells (sim/value_noise.h) and the layout
// of the field cell (120 m, many tiles) the last texel lay in, a pure memo (values do not depend on it); and
// the buffers of a row, kept so that no row allocates.
struct TextureMemo {
  NoiseMemo noise;
  FieldCellLayout fieldCell;
  std::vector<double> x, broad, grain;  // a row of texels: positions and noise
  struct Crowns {                       // a row of pixels: its crown hits, sampled together
    std::vector<double> x, y, shade;
    std::vector<float> footprint, value;
    std::vector<int> pixel;
  } crowns;
};

namespace {

// Salts of the independent noise layers.
enum Layer : std::uint32_t { kGrain = 1, kBroad, kRowBreaks, kTrack, kHedge, kCrown, kRoof, kCellLayout, kEdgeKind };

// The noise of the broad tone, the grain (2 cm - 1 m) and the crowns' leafy clumps.
constexpr Octaves kBroadOctaves{4.0, 64.0, 0.7}, kGrainOctaves{0.02, 1.28, 1.0}, kCrownOctaves{0.02, 2.56, 1.0};
constexpr Octaves kRaggedOctaves{0.5, 4.0, 0.8};  // a hedge's wandering width
constexpr double kBaseTexel_m = 0.01;  // the finest cached ground texels: half the footprint of a pixel at 30 m
constexpr double kTrackHalfWidth_m = 1.8, kRutOffset_m = 0.8, kRutHalfWidth_m = 0.2;
constexpr double kHedgeHalfWidth_m = 1.2, kVergeHalfWidth_m = 0.35, kRoofRim_m = 0.25;

// One per thread; a row of texels reaches it once.
TextureMemo& threadTextureMemo() {
  thread_local TextureMemo memo;
  return memo;
}

// How much of a pattern of wavelength `lambda` survives averaging over a
// pixel footprint: none at or below 2 footprints (the sampling's Nyquist
// limit, so nothing aliases), all from 4 footprints up.
double keep(double lambda, double footprint) { return std::clamp(lambda / (2.0 * footprint) - 1.0, 0.0, 1.0); }

// The part of a pixel footprint wide box filter inside a band of half-width
// `halfWidth` at distance d from its centre line: a sharp edge, anti-aliased.
double band(double d, double halfWidth, double footprint) {
  return std::clamp((halfWidth - std::abs(d)) / footprint + 0.5, 0.0, 1.0);
}

// A triangle wave of the given period, in [0, 1], faded to its mean 0.5 when finer than the footprint.
double rows(double s, double period, double footprint) {
  const double phase = s / period - std::floor(s / period);
  return 0.5 + keep(period, footprint) * (std::abs(2.0 * phase - 1.0) - 0.5);
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

}  // namespace

GroundTexture::GroundTexture(const GroundTextureOptions& options)
    : options_(options),
      groundTexels_(TexelTiles::RowFunction([this](std::int64_t ix, std::int64_t iy, double texel_m, int count,
                                                   float* out) { groundRow(ix, iy, texel_m, count, out); }),
                    kBaseTexel_m),
      crownTexels_(TexelTiles::RowFunction([this](std::int64_t ix, std::int64_t iy, double texel_m, int count,
                                                  float* out) { crownDetailRow(ix, iy, texel_m, count, out); }),
                   kBaseTexel_m) {
  const auto& o = options_;
  if (!(std::isfinite(o.fieldSize_m) && o.fieldSize_m > 0.0))
    throw Error("ground texture: fieldSize_m must be finite and > 0");
  if (!(o.trackProbability >= 0.0 && o.hedgeProbability >= 0.0 && o.trackProbability + o.hedgeProbability <= 1.0))
    throw Error("ground texture: trackProbability and hedgeProbability must be >= 0 and sum to at most 1");
  if (!(std::isfinite(o.grainContrast) && o.grainContrast >= 0.0))
    throw Error("ground texture: grainContrast must be finite and >= 0");
  salt_ = static_cast<std::uint32_t>(mixSeed(o.seed, 0x74657874));  // "text"
  const double angle = 0.5 * std::numbers::pi * hash01(0, 0, salt_);
  cosGrid_ = std::cos(angle);
  sinGrid_ = std::sin(angle);
}

float GroundTexture::grey(const SurfaceHit& hit, double footprint_m) const {
  if (hit.tree) return tree(hit, footprint_m);
  if (hit.building) return building(hit, footprint_m);
  return groundTexels_.sample(hit.point.x(), hit.point.y(), footprint_m);
}

void GroundTexture::greyRow(const RowHits& row, float* out) const {
  // The ground under every pixel in one pass (TexelTiles::sampleMany), then the obstacle pixels over it: crowns
  // gathered and sampled from their cache together, roofs and walls one by one.
  groundTexels_.sampleMany(row.x.data(), row.y.data(), row.footprint_m.data(), row.size(), out);
  TextureMemo::Crowns& crowns = threadTextureMemo().crowns;
  crowns.x.clear(), crowns.y.clear(), crowns.shade.clear(), crowns.footprint.clear(), crowns.pixel.clear();
  const Terrain::Tree* toned = nullptr;  // a crown's pixels lie side by side: its tone is hashed once for them
  double tone = 0.0;
  for (const RowHits::Obstacle& obstacle : row.obstacles) {
    const SurfaceHit& hit = obstacle.hit;
    if (hit.building) {
      out[obstacle.pixel] = building(hit, obstacle.footprint_m);
      continue;
    }
    if (hit.tree != toned) toned = hit.tree, tone = crownTone(*toned);
    crowns.x.push_back(hit.point.x()), crowns.y.push_back(hit.point.y());
    crowns.shade.push_back(crownShade(hit, tone));
    crowns.footprint.push_back(obstacle.footprint_m), crowns.pixel.push_back(obstacle.pixel);
  }
  const int count = static_cast<int>(crowns.pixel.size());
  crowns.value.resize(count);
  crownTexels_.sampleMany(crowns.x.data(), crowns.y.data(), crowns.footprint.data(), count, crowns.value.data());
  for (int k = 0; k < count; ++k) out[crowns.pixel[k]] = crownGrey(crowns.shade[k], crowns.value[k]);
}

void GroundTexture::prepare(const SurfaceRegions& seen, int threads) const {
  groundTexels_.require(seen.ground, threads, seen.rowDirection);
  crownTexels_.require(seen.crowns, threads, seen.rowDirection);
}

const FieldCellLayout& GroundTexture::fieldCell(std::int64_t i, std::int64_t j, TextureMemo& memo) const {
  FieldCellLayout& cell = memo.fieldCell;
  if (cell.filled && cell.i == i && cell.j == j) return cell;
  const std::uint32_t layout = salt_ + kCellLayout;
  cell.filled = true, cell.i = i, cell.j = j;
  cell.splitAcrossU = hash01(i, j, layout);
  cell.splitAt = hash01(i, j, layout + 5);
  cell.splitHedge = hash01(i, j, layout + 6);
  for (int half = 0; half < 2; ++half)
    for (std::uint32_t k = 0; k < 4; ++k) cell.fields[half][k] = hash01(2 * i + half, j, layout + 1 + k);
  // An edge is keyed by the cell it starts: this cell's, and the next cell's along the axis.
  const std::int64_t endKeys[2][2] = {{i + 1, j}, {i, j + 1}};
  for (std::uint32_t axis = 0; axis < 2; ++axis) {
    cell.edgeKinds[axis] = {hash01(i, j, salt_ + kEdgeKind + axis),
                            hash01(endKeys[axis][0], endKeys[axis][1], salt_ + kEdgeKind + axis)};
    cell.trackTones[axis] = {hash01(i, j, salt_ + kTrack), hash01(endKeys[axis][0], endKeys[axis][1], salt_ + kTrack)};
  }
  return cell;
}

float GroundTexture::field(double u, double v, const std::array<double, 4>& hashes, double footprint_m,
                           TextureMemo& memo) const {
  const double kind = hashes[0], shade = hashes[1], spacing = hashes[3];
  const bool alongU = hashes[2] < 0.5;
  double grey, period, contrast;
  if (kind < 0.4) {  // ploughed soil: dark, fine furrows
    grey = lerp(70.0, 120.0, shade), period = lerp(0.3, 0.8, spacing), contrast = 0.3;
  } else if (kind < 0.7) {  // a crop in rows
    grey = lerp(100.0, 160.0, shade), period = lerp(0.5, 1.5, spacing), contrast = 0.25;
  } else {  // pasture: no rows, patchy
    grey = lerp(110.0, 170.0, shade), period = 0.0, contrast = 0.0;
  }
  const double across = alongU ? v : u, along = alongU ? u : v;
  if (period > 0.0) {
    // Rows broken up along their length (plants, clods), so row texture has corners too.
    const double breaks =
        0.5 + fractal(along, across / period, {0.1, 0.8, 0.8}, footprint_m, salt_ + kRowBreaks, memo.noise);
    grey *= 1.0 + contrast * (2.0 * rows(across, period, footprint_m) - 1.0) * (0.4 + 1.2 * breaks);
  } else {
    grey *= 1.0 + 0.5 * fractal(u, v, {1.0, 16.0, 0.7}, footprint_m, salt_ + kBroad + 7, memo.noise);
  }
  return static_cast<float>(grey);
}

float GroundTexture::ground(double x, double y, double footprint_m) const {
  TextureMemo& memo = threadTextureMemo();
  return groundAt(x, y, footprint_m, fractal(x, y, kBroadOctaves, footprint_m, salt_ + kBroad, memo.noise),
                  fractal(x, y, kGrainOctaves, footprint_m, salt_ + kGrain, memo.noise), memo);
}

void GroundTexture::groundRow(std::int64_t ix, std::int64_t iy, double texel_m, int count, float* out) const {
  // The broad tone and the grain over the whole row first (value_noise.h's four-point path), then the rest
  // of each texel.
  TextureMemo& memo = threadTextureMemo();
  memo.x.resize(count), memo.broad.resize(count), memo.grain.resize(count);
  const double y = static_cast<double>(iy) * texel_m;
  for (int n = 0; n < count; ++n) memo.x[n] = static_cast<double>(ix + n) * texel_m;
  fractalRow(memo.x.data(), y, count, kBroadOctaves, texel_m, salt_ + kBroad, memo.noise, memo.broad.data());
  fractalRow(memo.x.data(), y, count, kGrainOctaves, texel_m, salt_ + kGrain, memo.noise, memo.grain.data());
  for (int n = 0; n < count; ++n) out[n] = groundAt(memo.x[n], y, texel_m, memo.broad[n], memo.grain[n], memo);
}

float GroundTexture::groundAt(double x, double y, double footprint_m, double broad, double grain,
                              TextureMemo& memo) const {
  const double size = options_.fieldSize_m;
  const double u = cosGrid_ * x + sinGrid_ * y, v = -sinGrid_ * x + cosGrid_ * y;
  const double fi = std::floor(u / size), fj = std::floor(v / size);
  const auto i = static_cast<std::int64_t>(fi), j = static_cast<std::int64_t>(fj);
  const double cu = u - fi * size, cv = v - fj * size;  // within the cell
  const FieldCellLayout& cell = fieldCell(i, j, memo);
  // Each cell is split in two across u or v at 30-70 %.
  const bool splitU = cell.splitAcrossU < 0.5;
  const double splitAt = size * lerp(0.3, 0.7, cell.splitAt);
  const double splitDistance = (splitU ? cu : cv) - splitAt;
  const int half = splitDistance < 0.0 ? 0 : 1;
  double grey = field(u, v, cell.fields[half], footprint_m, memo);
  grey *= 1.0 + 0.3 * broad;

  // The nearest cell edge in u and in v, each a track, hedge or verge by its own hash.
  auto edgeStrip = [&](double distance, int axis, int end) {
    const double pick = cell.edgeKinds[axis][end];
    const double along = axis == 0 ? v : u;
    if (pick < options_.trackProbability) {
      const double inside = band(distance, kTrackHalfWidth_m, footprint_m);
      if (inside <= 0.0) return;
      const double ruts = band(std::abs(distance) - kRutOffset_m, kRutHalfWidth_m, footprint_m);
      const double gravel =
          1.0 + 0.6 * fractal(along, distance, {0.02, 0.64, 0.9}, footprint_m, salt_ + kTrack, memo.noise);
      const double track = lerp(lerp(175.0, 205.0, cell.trackTones[axis][end]), 120.0, ruts) * gravel;
      grey = lerp(grey, track, inside);
    } else if (pick < options_.trackProbability + options_.hedgeProbability) {
      // Hedges are ragged: their half-width wanders along them (computed only where it can reach the texel).
      static const double widest = kHedgeHalfWidth_m * (1.0 + 0.6 * fractalBound(kRaggedOctaves));
      if (band(distance, widest, footprint_m) <= 0.0) return;
      const double ragged =
          kHedgeHalfWidth_m * (1.0 + 0.6 * fractal(along, 0.0, kRaggedOctaves, 0.0, salt_ + kHedge, memo.noise));
      const double inside = band(distance, ragged, footprint_m);
      if (inside <= 0.0) return;
      const double leaves =
          1.0 + 1.2 * fractal(along, distance, {0.04, 1.28, 0.85}, footprint_m, salt_ + kHedge + 1, memo.noise);
      grey = lerp(grey, 55.0 * leaves, inside);
    } else {
      grey = lerp(grey, 140.0, band(distance, kVergeHalfWidth_m, footprint_m));
    }
  };
  if (cu < 0.5 * size)
    edgeStrip(cu, 0, 0);
  else
    edgeStrip(cu - size, 0, 1);
  if (cv < 0.5 * size)
    edgeStrip(cv, 1, 0);
  else
    edgeStrip(cv - size, 1, 1);
  // The split line: a hedge or a verge.
  if (cell.splitHedge < options_.hedgeProbability) {
    const double inside = band(splitDistance, kHedgeHalfWidth_m, footprint_m);
    if (inside > 0.0)
      grey = lerp(grey,
                  55.0 * (1.0 + 1.2 * fractal(u, v, {0.04, 1.28, 0.85}, footprint_m, salt_ + kHedge + 2, memo.noise)),
                  inside);
  } else {
    grey = lerp(grey, 140.0, band(splitDistance, kVergeHalfWidth_m, footprint_m));
  }
  return static_cast<float>(std::clamp(grey * (1.0 + options_.grainContrast * 2.0 * grain), 0.0, 255.0));
}

float GroundTexture::tree(const SurfaceHit& hit, double footprint_m) const {
  return crownGrey(crownShade(hit, crownTone(*hit.tree)),
                   crownTexels_.sample(hit.point.x(), hit.point.y(), footprint_m));
}

float GroundTexture::crownGrey(double shade, float detail) {
  return static_cast<float>(std::clamp(shade * detail, 0.0, 255.0));
}

double GroundTexture::crownTone(const Terrain::Tree& t) const {
  return lerp(45.0, 80.0, hash01(std::llround(t.centre.x() * 10.0), std::llround(t.centre.y() * 10.0), salt_ + kCrown));
}

double GroundTexture::crownShade(const SurfaceHit& hit, double tone) const {
  const Terrain::Tree& t = *hit.tree;
  const double r2 = std::min(1.0, (hit.point.head<2>() - t.centre).squaredNorm() / (t.radius * t.radius));
  const double shading = 0.55 + 0.45 * std::sqrt(1.0 - r2);
  return tone * shading;
}

float GroundTexture::crownDetail(double x, double y, double footprint_m) const {
  return static_cast<float>(1.0 +
                            2.0 * fractal(x, y, kCrownOctaves, footprint_m, salt_ + kCrown, threadTextureMemo().noise));
}

void GroundTexture::crownDetailRow(std::int64_t ix, std::int64_t iy, double texel_m, int count, float* out) const {
  TextureMemo& memo = threadTextureMemo();
  memo.x.resize(count), memo.grain.resize(count);
  for (int n = 0; n < count; ++n) memo.x[n] = static_cast<double>(ix + n) * texel_m;
  fractalRow(memo.x.data(), static_cast<double>(iy) * texel_m, count, kCrownOctaves, texel_m, salt_ + kCrown,
             memo.noise, memo.grain.data());
  for (int n = 0; n < count; ++n) out[n] = static_cast<float>(1.0 + 2.0 * memo.grain[n]);
}

float GroundTexture::building(const SurfaceHit& hit, double footprint_m) const {
  const Terrain::Building& b = *hit.building;
  if (hit.point.z() < b.roof - 1e-6) return 90.0f;  // a wall
  const Eigen::Vector2d d = hit.point.head<2>() - b.centre;
  const double along = b.cosHeading * d.x() + b.sinHeading * d.y();
  const double across = -b.sinHeading * d.x() + b.cosHeading * d.y();
  const double tone =
      lerp(160.0, 215.0, hash01(std::llround(b.centre.x() * 10.0), std::llround(b.centre.y() * 10.0), salt_ + kRoof));
  const double toEdge = std::min(b.halfSize.x() - std::abs(along), b.halfSize.y() - std::abs(across));
  const double rim = band(toEdge, kRoofRim_m, footprint_m);
  const double corrugation = 1.0 + 0.12 * (2.0 * rows(along, 0.4, footprint_m) - 1.0);
  const double weathering =
      1.0 + 0.3 * fractal(along, across, {0.05, 2.0, 0.8}, footprint_m, salt_ + kRoof + 1, threadTextureMemo().noise);
  return static_cast<float>(std::clamp(lerp(tone * corrugation * weathering, 80.0, rim), 0.0, 255.0));
}

}  // namespace lrsvo
