#include "lrsvo/sim/terrain.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"

namespace lrsvo {
namespace {

constexpr int kWaves = 6;
constexpr double kCrownRadiusPerHeight = 0.3;  // a 12 m tree has a crown about 7 m across
constexpr double kMinCellSize_m = 50.0;
constexpr double kWorldLimit_m = 1e9;              // keeps every cell index well inside int64
constexpr std::uint64_t kWaveStream = 0x77617665;  // "wave"

void check(bool condition, const std::string& message) {
  if (!condition) throw Error("terrain: " + message);
}

void validate(const TerrainOptions& o) {
  check(std::isfinite(o.relief_m) && o.relief_m >= 0.0, "relief_m must be finite and >= 0");
  check(std::isfinite(o.hillScale_m) && o.hillScale_m > 0.0, "hillScale_m must be finite and > 0");
  check(std::isfinite(o.treeDensity_per_km2) && o.treeDensity_per_km2 >= 0.0 &&
            std::isfinite(o.buildingDensity_per_km2) && o.buildingDensity_per_km2 >= 0.0,
        "tree and building densities must be finite and >= 0");
  check(std::isfinite(o.treeHeight_m) && o.treeHeight_m >= 0.0 && std::isfinite(o.buildingHeight_m) &&
            o.buildingHeight_m >= 0.0,
        "tree and building heights must be finite and >= 0");
  check(std::isfinite(o.buildingSize_m) && o.buildingSize_m > 0.0, "buildingSize_m must be finite and > 0");
}

template <typename Generator>
double uniform(Generator& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

int poisson(SplitMix64& rng, double mean) { return mean > 0.0 ? std::poisson_distribution<int>(mean)(rng) : 0; }

}  // namespace

Terrain::Terrain(const TerrainOptions& options) : options_(options) {
  validate(options_);
  // A few waves in random directions with wavelengths of half to twice the
  // hill scale, longer waves taller, amplitudes summing to the relief.
  std::mt19937_64 rng(mixSeed(options_.seed, kWaveStream));
  double amplitudeSum = 0.0;
  for (int i = 0; i < kWaves; ++i) {
    const double direction = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    const double wavelength = options_.hillScale_m * std::exp2(uniform(rng, -1.0, 1.0));
    const double k = 2.0 * std::numbers::pi / wavelength;
    waves_.push_back({k * Eigen::Vector2d(std::cos(direction), std::sin(direction)), wavelength,
                      uniform(rng, 0.0, 2.0 * std::numbers::pi)});
    amplitudeSum += wavelength;
  }
  for (Wave& wave : waves_) wave.amplitude *= options_.relief_m / amplitudeSum;
  // An obstacle centred in a cell reaches at most its neighbours.
  const double treeRadius = kCrownRadiusPerHeight * options_.treeHeight_m;
  const double buildingRadius = 0.75 * options_.buildingSize_m * std::numbers::sqrt2;
  cellSize_m_ = std::max(kMinCellSize_m, 2.0 * std::max(treeRadius, buildingRadius));
}

double Terrain::groundHeight(double x, double y) const {
  double z = 0.0;
  for (const Wave& wave : waves_)
    z += wave.amplitude * std::sin(wave.wavenumber.dot(Eigen::Vector2d(x, y)) + wave.phase);
  return z;
}

double Terrain::minHeight() const { return -options_.relief_m; }

double Terrain::maxHeight() const {
  return options_.relief_m + std::max(options_.treeHeight_m, options_.buildingHeight_m);
}

Terrain::Cell Terrain::makeCell(std::int64_t ix, std::int64_t iy) const {
  SplitMix64 rng(mixSeed(options_.seed, static_cast<std::uint64_t>(ix), static_cast<std::uint64_t>(iy)));
  const double areaKm2 = cellSize_m_ * cellSize_m_ * 1e-6;
  const Eigen::Vector2d corner(ix * cellSize_m_, iy * cellSize_m_);
  auto position = [&]() -> Eigen::Vector2d {
    return corner + Eigen::Vector2d(uniform(rng, 0.0, cellSize_m_), uniform(rng, 0.0, cellSize_m_));
  };
  Cell cell;
  const int trees = poisson(rng, options_.treeDensity_per_km2 * areaKm2);
  for (int i = 0; i < trees; ++i) {
    const Eigen::Vector2d centre = position();
    const double height = options_.treeHeight_m * uniform(rng, 0.5, 1.0);
    cell.trees.push_back({centre, kCrownRadiusPerHeight * height, groundHeight(centre.x(), centre.y()), height});
  }
  const int buildings = poisson(rng, options_.buildingDensity_per_km2 * areaKm2);
  for (int i = 0; i < buildings; ++i) {
    const Eigen::Vector2d centre = position();
    const Eigen::Vector2d halfSize =
        0.5 * options_.buildingSize_m * Eigen::Vector2d(uniform(rng, 0.5, 1.5), uniform(rng, 0.5, 1.5));
    const double heading = uniform(rng, 0.0, std::numbers::pi);
    const double roof = groundHeight(centre.x(), centre.y()) + options_.buildingHeight_m * uniform(rng, 0.5, 1.0);
    cell.buildings.push_back({centre, halfSize, std::cos(heading), std::sin(heading), roof});
  }
  return cell;
}

const Terrain::Cell& Terrain::cell(std::int64_t ix, std::int64_t iy, CellCache& cache) const {
  const auto key = std::make_pair(ix, iy);
  auto found = cache.find(key);
  if (found == cache.end()) found = cache.emplace(key, makeCell(ix, iy)).first;
  return found->second;
}

double Terrain::height(double x, double y, CellCache& cache) const {
  check(std::abs(x) <= kWorldLimit_m && std::abs(y) <= kWorldLimit_m,
        "height asked at a non-finite position or beyond the world's +-1e9 m");
  double z = groundHeight(x, y);
  const auto ix = static_cast<std::int64_t>(std::floor(x / cellSize_m_));
  const auto iy = static_cast<std::int64_t>(std::floor(y / cellSize_m_));
  const Eigen::Vector2d p(x, y);
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      const Cell& c = cell(ix + dx, iy + dy, cache);
      for (const Tree& tree : c.trees) {
        const double r2 = (p - tree.centre).squaredNorm() / (tree.radius * tree.radius);
        if (r2 < 1.0) z = std::max(z, tree.base + tree.height * std::sqrt(1.0 - r2));
      }
      for (const Building& b : c.buildings) {
        const Eigen::Vector2d d = p - b.centre;
        const double along = b.cosHeading * d.x() + b.sinHeading * d.y();
        const double across = -b.sinHeading * d.x() + b.cosHeading * d.y();
        if (std::abs(along) < b.halfSize.x() && std::abs(across) < b.halfSize.y()) z = std::max(z, b.roof);
      }
    }
  }
  return z;
}

Terrain::Obstacles Terrain::obstaclesIn(const Eigen::AlignedBox2d& box) const {
  check(box.min().allFinite() && box.max().allFinite() && box.max().cwiseAbs().maxCoeff() <= kWorldLimit_m &&
            box.min().cwiseAbs().maxCoeff() <= kWorldLimit_m,
        "obstaclesIn needs a finite box within the world's +-1e9 m");
  // An obstacle reaches at most one cell beyond its own.
  const auto first = (box.min() / cellSize_m_).array().floor().cast<std::int64_t>() - 1;
  const auto last = (box.max() / cellSize_m_).array().floor().cast<std::int64_t>() + 1;
  Obstacles obstacles;
  for (std::int64_t ix = first.x(); ix <= last.x(); ++ix) {
    for (std::int64_t iy = first.y(); iy <= last.y(); ++iy) {
      const Cell c = makeCell(ix, iy);
      obstacles.trees.insert(obstacles.trees.end(), c.trees.begin(), c.trees.end());
      obstacles.buildings.insert(obstacles.buildings.end(), c.buildings.begin(), c.buildings.end());
    }
  }
  return obstacles;
}

double Terrain::height(double x, double y) const {
  CellCache cache;
  return height(x, y, cache);
}

std::vector<Eigen::Vector3d> Terrain::samplePoints(const Eigen::Vector2d& min, const Eigen::Vector2d& max, int count,
                                                   std::uint64_t seed) const {
  check(min.allFinite() && max.allFinite() && (min.array() <= max.array()).all(),
        "samplePoints needs a finite rectangle with min <= max");
  check(count >= 0, "samplePoints needs count >= 0, got " + std::to_string(count));
  std::mt19937_64 rng(seed);
  CellCache cache;
  std::vector<Eigen::Vector3d> points;
  points.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double x = uniform(rng, min.x(), max.x()), y = uniform(rng, min.y(), max.y());
    points.emplace_back(x, y, height(x, y, cache));
  }
  return points;
}

}  // namespace lrsvo
