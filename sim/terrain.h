#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace lrsvo {

// A seeded, unbounded world surface (world z up, metres): rolling farmland
// with trees and buildings on it. Defaults: gentle relief of a few metres
// over hundreds of metres, scattered trees and a few farm buildings, like
// the rural farmland of the paper's flight.
struct TerrainOptions {
  double relief_m = 8.0;       // sum of the rolling waves' amplitudes: the ground stays within +- relief_m of z = 0
  double hillScale_m = 300.0;  // typical horizontal wavelength of the relief
  double treeDensity_per_km2 = 2000.0;
  double treeHeight_m = 12.0;  // tallest tree; each is an ellipsoid crown of 0.5-1 times this height
  double buildingDensity_per_km2 = 50.0;
  double buildingHeight_m = 8.0;  // tallest building; each is a box of 0.5-1 times this height
  double buildingSize_m = 15.0;   // typical side; each side 0.5-1.5 times this
  std::uint64_t seed = 1;
};

class Terrain {
 public:
  // Throws lrsvo::Error on negative or non-finite sizes and densities.
  explicit Terrain(const TerrainOptions& options);

  // World z of the surface (ground, tree crown or roof) at (x, y); the same
  // options always give the same surface.
  double height(double x, double y) const;
  // The rolling ground alone, without trees and buildings; its mean is 0.
  double groundHeight(double x, double y) const;
  // Bounds on height() anywhere: -relief and relief + the tallest obstacle.
  double minHeight() const;
  double maxHeight() const;

  // `count` points uniform in x, y over the rectangle [min, max], on the
  // surface (z = height(x, y)); the same arguments give the same points.
  std::vector<Eigen::Vector3d> samplePoints(const Eigen::Vector2d& min, const Eigen::Vector2d& max, int count,
                                            std::uint64_t seed) const;

  // The obstacles on the ground: an ellipsoid crown (upper half, semi-axes
  // radius, radius, height, centred on the ground at its trunk) and a box
  // with a flat roof, reaching down into the ground.
  struct Tree {
    Eigen::Vector2d centre;
    double radius;
    double base;  // ground height at the trunk
    double height;
  };
  struct Building {
    Eigen::Vector2d centre;
    Eigen::Vector2d halfSize;  // along its own axes
    double cosHeading, sinHeading;
    double roof;  // world z of the flat roof
  };
  struct Obstacles {
    std::vector<Tree> trees;
    std::vector<Building> buildings;
  };
  // Every tree and building whose footprint may reach into the box (x, y):
  // those that shape height() there, and perhaps a few more nearby.
  Obstacles obstaclesIn(const Eigen::AlignedBox2d& box) const;

 private:
  struct Wave {
    Eigen::Vector2d wavenumber;  // rad/m along the wave's direction
    double amplitude;
    double phase;
  };
  struct Cell {
    std::vector<Tree> trees;
    std::vector<Building> buildings;
  };
  // Obstacles are generated per square cell from a seed mixed with the cell's
  // indices, so any part of the unbounded world is reproducible on demand.
  using CellCache = std::map<std::pair<std::int64_t, std::int64_t>, Cell>;

  Cell makeCell(std::int64_t ix, std::int64_t iy) const;
  const Cell& cell(std::int64_t ix, std::int64_t iy, CellCache& cache) const;
  double height(double x, double y, CellCache& cache) const;

  TerrainOptions options_;
  std::vector<Wave> waves_;
  double cellSize_m_ = 0.0;
};

}  // namespace lrsvo
