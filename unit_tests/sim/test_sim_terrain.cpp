#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/terrain.h"

namespace lrsvo {
namespace {

// Fraction of uniform samples over [0, side]^2 that stand above the bare ground.
double coveredFraction(const Terrain& terrain, double side, int samples) {
  int covered = 0;
  for (const Eigen::Vector3d& p : terrain.samplePoints({0.0, 0.0}, {side, side}, samples, 5))
    covered += p.z() > terrain.groundHeight(p.x(), p.y()) ? 1 : 0;
  return static_cast<double>(covered) / samples;
}

TEST(SimTerrain, HeightIsDeterministicAndWithinReliefAndObstacleBounds) {
  const TerrainOptions options;
  const Terrain a(options), b(options);
  EXPECT_DOUBLE_EQ(a.minHeight(), -8.0);
  EXPECT_DOUBLE_EQ(a.maxHeight(), 8.0 + 12.0);
  double lowest = 0.0, highest = 0.0;
  for (double x = -600.0; x <= 600.0; x += 19.7) {
    for (double y = -600.0; y <= 600.0; y += 27.1) {
      const double z = a.height(x, y);
      EXPECT_EQ(z, b.height(x, y));
      EXPECT_EQ(z, a.height(x, y));
      EXPECT_GE(z, a.groundHeight(x, y));
      EXPECT_LE(std::abs(a.groundHeight(x, y)), 8.0);
      EXPECT_GE(z, a.minHeight());
      EXPECT_LE(z, a.maxHeight());
      lowest = std::min(lowest, z);
      highest = std::max(highest, z);
    }
  }
  // Real relief: over 1.2 km the surface spans several metres.
  EXPECT_GT(highest - lowest, 8.0);
}

TEST(SimTerrain, FlatEmptyWorldIsTheZeroPlane) {
  TerrainOptions options;
  options.relief_m = 0.0;
  options.treeDensity_per_km2 = 0.0;
  options.buildingDensity_per_km2 = 0.0;
  const Terrain terrain(options);
  for (double x = -500.0; x <= 500.0; x += 37.0) EXPECT_EQ(terrain.height(x, 0.3 * x - 20.0), 0.0);
}

TEST(SimTerrain, TreesCoverTheExpectedShareOfTheGroundAndStayBelowTheirHeight) {
  TerrainOptions options;
  options.relief_m = 0.0;
  options.buildingDensity_per_km2 = 0.0;
  const Terrain terrain(options);
  // Crowns of radius 0.3 h, h uniform in [6, 12] m: mean area pi 0.09 E[h^2] = 23.75 m^2;
  // 2000 per km^2 (Poisson) cover 1 - exp(-0.002 * 23.75) = 4.64 % of the ground.
  EXPECT_NEAR(coveredFraction(terrain, 2000.0, 50000), 0.0464, 0.005);
  for (const Eigen::Vector3d& p : terrain.samplePoints({0.0, 0.0}, {500.0, 500.0}, 20000, 3)) EXPECT_LE(p.z(), 12.0);
}

TEST(SimTerrain, BuildingsCoverTheExpectedShareWithFlatRoofs) {
  TerrainOptions options;
  options.relief_m = 0.0;
  options.treeDensity_per_km2 = 0.0;
  const Terrain terrain(options);
  // Sides 0.5-1.5 times 15 m: mean area 225 m^2; 50 per km^2 cover 1 - exp(-0.01125) = 1.12 %.
  EXPECT_NEAR(coveredFraction(terrain, 2000.0, 50000), 0.0112, 0.003);
  for (const Eigen::Vector3d& p : terrain.samplePoints({0.0, 0.0}, {1000.0, 1000.0}, 20000, 4))
    EXPECT_TRUE(p.z() == 0.0 || (p.z() >= 4.0 && p.z() <= 8.0)) << p.z();  // roofs 0.5-1 times 8 m
}

TEST(SimTerrain, SamplePointsLieOnTheSurfaceInsideTheRectangleAndFollowTheirSeed) {
  const Terrain terrain(TerrainOptions{});
  const Eigen::Vector2d min(-50.0, 20.0), max(150.0, 60.0);
  const std::vector<Eigen::Vector3d> points = terrain.samplePoints(min, max, 500, 9);
  ASSERT_EQ(points.size(), 500u);
  for (const Eigen::Vector3d& p : points) {
    EXPECT_TRUE(p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y());
    EXPECT_EQ(p.z(), terrain.height(p.x(), p.y()));
  }
  EXPECT_EQ(points, terrain.samplePoints(min, max, 500, 9));
  EXPECT_NE(points, terrain.samplePoints(min, max, 500, 10));
}

TEST(SimTerrain, OtherSeedOtherWorld) {
  TerrainOptions options;
  const Terrain a(options);
  options.seed = 2;
  const Terrain b(options);
  int different = 0;
  for (double x = 0.0; x < 1000.0; x += 50.0) different += a.height(x, 0.0) != b.height(x, 0.0) ? 1 : 0;
  EXPECT_EQ(different, 20);
}

TEST(SimTerrain, BadOptionsThrow) {
  const auto throws = [](auto edit) {
    TerrainOptions options;
    edit(options);
    EXPECT_THROW(Terrain{options}, Error);
  };
  throws([](TerrainOptions& o) { o.relief_m = -1.0; });
  throws([](TerrainOptions& o) { o.hillScale_m = 0.0; });
  throws([](TerrainOptions& o) { o.treeDensity_per_km2 = -1.0; });
  throws([](TerrainOptions& o) { o.buildingHeight_m = NAN; });
  throws([](TerrainOptions& o) { o.buildingSize_m = 0.0; });
  const Terrain terrain(TerrainOptions{});
  EXPECT_THROW(terrain.samplePoints({1.0, 0.0}, {0.0, 1.0}, 10, 1), Error);
  EXPECT_THROW(terrain.samplePoints({0.0, 0.0}, {1.0, 1.0}, -1, 1), Error);
  EXPECT_THROW(terrain.height(NAN, 0.0), Error);
  EXPECT_THROW(terrain.height(0.0, 1e12), Error);
}

}  // namespace
}  // namespace lrsvo
