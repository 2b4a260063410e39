#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lrsvo/graph/error.h"
#include "lrsvo/sim/euroc_writer.h"
#include "lrsvo/sim/ground_texture.h"
#include "lrsvo/sim/image_renderer.h"
#include "lrsvo/sim/scenario.h"
#include "lrsvo/sim/sim_frame_source.h"
#include "lrsvo/sim/surface_view.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

TerrainOptions flatTerrain() {
  TerrainOptions options;
  options.relief_m = 0.0;
  options.treeDensity_per_km2 = 0.0;
  options.buildingDensity_per_km2 = 0.0;
  return options;
}

// A base camera at `centre` looking straight down, x along world x (flight direction), z down.
Eigen::Isometry3d nadirCameraFromWorld(const Eigen::Vector3d& centre) {
  Eigen::Matrix3d worldFromCamera;
  worldFromCamera.col(0) = Eigen::Vector3d::UnitX();
  worldFromCamera.col(1) = -Eigen::Vector3d::UnitY();
  worldFromCamera.col(2) = -Eigen::Vector3d::UnitZ();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = worldFromCamera.transpose();
  pose.translation() = -worldFromCamera.transpose() * centre;
  return pose;
}

RenderOptions sceneOnly() {
  RenderOptions options;
  options.noiseSigma_grey = 0.0;
  options.blurSigma_px = 0.0;
  options.exposureDrift = 0.0;
  return options;
}

Camera smallCamera() { return paperRig(0.7, 320, 240).cameras[0]; }

// Dark for x < edge, bright beyond, box-filtered over the footprint: the edge crosses grey 125 exactly at x = edge.
class StepTexture : public SurfaceTexture {
 public:
  explicit StepTexture(double edge) : edge_(edge) {}
  float grey(const SurfaceHit& hit, double footprint_m) const override {
    return static_cast<float>(50.0 + 150.0 * std::clamp((hit.point.x() - edge_) / footprint_m + 0.5, 0.0, 1.0));
  }

 private:
  double edge_;
};

class ConstantTexture : public SurfaceTexture {
 public:
  float grey(const SurfaceHit&, double) const override { return 128.0f; }
};

// A tilted, yawed camera over hilly ground with many crowns and roofs.
Eigen::Isometry3d obliqueCameraFromWorld() {
  return Eigen::Isometry3d(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(0.15, Eigen::Vector3d::UnitX()) *
                           Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitY())) *
         nadirCameraFromWorld({100.0, 50.0, 45.0});
}

TerrainOptions crowdedTerrain() {
  TerrainOptions options;
  options.treeDensity_per_km2 = 20000.0;
  options.buildingDensity_per_km2 = 2000.0;
  options.seed = 3;
  return options;
}

TEST(ImageRendererGeometry, EdgeOnTheGroundAppearsWhereThePinholeModelProjectsIt) {
  const Terrain terrain(flatTerrain());
  const double edge = 1.234;
  const StepTexture texture(edge);
  const Camera camera = smallCamera();
  // A tilted, yawed camera 40 m up, so the edge runs obliquely through the image.
  Eigen::Isometry3d pose = nadirCameraFromWorld({0.0, 0.0, 40.0});
  pose = Eigen::Isometry3d(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) *
                           Eigen::AngleAxisd(-0.05, Eigen::Vector3d::UnitY())) *
         pose;
  const cv::Mat scene = ImageRenderer(terrain, texture, sceneOnly(), 1).renderScene(camera, pose);
  // The edge's image: the line through the projections of two of its world points.
  const Eigen::Vector2d a = camera.intrinsics.project(pose * Eigen::Vector3d(edge, -20.0, 0.0));
  const Eigen::Vector2d b = camera.intrinsics.project(pose * Eigen::Vector3d(edge, 20.0, 0.0));
  double worst = 0.0;
  int rows = 0;
  for (int v = 10; v < camera.height - 10; ++v) {
    const double expected = a.x() + (v - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (expected < 5.0 || expected > camera.width - 6.0) continue;
    // Where the row crosses grey 125, by linear interpolation between the pixels around it.
    const float* row = scene.ptr<float>(v);
    const int u0 = static_cast<int>(std::floor(expected)) - 3;
    double found = -1.0;
    for (int u = u0; u < u0 + 7; ++u)
      if ((row[u] - 125.0f) * (row[u + 1] - 125.0f) <= 0.0f && row[u] != row[u + 1])
        found = u + (125.0 - row[u]) / (row[u + 1] - row[u]);
    ASSERT_GE(found, 0.0) << "row " << v;
    worst = std::max(worst, std::abs(found - expected));
    ++rows;
  }
  EXPECT_GT(rows, 150);
  EXPECT_LT(worst, 0.12);  // pixels
}

TEST(ImageRendererGeometry, StereoDisparityOfFlatGroundIsFocalTimesBaselineOverHeight) {
  const Terrain terrain(flatTerrain());
  const GroundTexture texture(GroundTextureOptions{});
  const Rig rig = paperRig(0.7, 320, 240);
  const double height = 30.0;
  const Eigen::Isometry3d base = nadirCameraFromWorld({10.0, 20.0, height});
  const ImageRenderer renderer(terrain, texture, sceneOnly(), 1);
  const cv::Mat left = renderer.renderScene(rig.cameras[0], rig.cameraFromWorld(base, 0));
  const cv::Mat right = renderer.renderScene(rig.cameras[1], rig.cameraFromWorld(base, 1));
  const double expected = rig.cameras[0].intrinsics.fx * 0.7 / height;  // 9.7 px
  // Block matching over the whole image: the sub-pixel shift of the right image that best matches the left.
  const cv::Rect inside(20, 10, left.cols - 40, left.rows - 20);
  double best = 0.0, bestCost = 1e300;
  for (double d = 8.0; d <= 11.5; d += 0.01) {
    const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1.0, 0.0, d, 0.0, 1.0, 0.0);
    cv::Mat moved;
    cv::warpAffine(right, moved, shift, right.size(), cv::INTER_CUBIC);
    const double cost = cv::norm(moved(inside), left(inside), cv::NORM_L2SQR);
    if (cost < bestCost) bestCost = cost, best = d;
  }
  // Block matching on textured images recovers it to a few hundredths of a pixel (measured: 9.77).
  EXPECT_NEAR(best, expected, 0.06);
  // Exactly in the geometry: the ground point seen at (u, v) in the left camera is seen at (u - fb/H, v) in the right.
  const SurfaceView leftView(terrain, rig.cameras[0], rig.cameraFromWorld(base, 0));
  const SurfaceView rightView(terrain, rig.cameras[1], rig.cameraFromWorld(base, 1));
  for (const Eigen::Vector2d& pixel :
       {Eigen::Vector2d(50.0, 40.0), Eigen::Vector2d(160.3, 120.7), Eigen::Vector2d(300.0, 230.0)}) {
    const Eigen::Vector3d seen = leftView.hit(pixel.x(), pixel.y()).point;
    EXPECT_NEAR(seen.z(), 0.0, 1e-9);
    EXPECT_LT((rightView.hit(pixel.x() - expected, pixel.y()).point - seen).norm(), 1e-6);
  }
  // The same from phase correlation (whose sub-pixel peak is biased by a few hundredths of a pixel).
  cv::Mat window;
  cv::createHanningWindow(window, left.size(), CV_32F);
  const cv::Point2d measured = cv::phaseCorrelate(left, right, window);
  EXPECT_NEAR(-measured.x, expected, 0.15);
  EXPECT_NEAR(measured.y, 0.0, 0.15);
}

TEST(ImageRendererGeometry, RaysMeetTheTerrainSurfaceWithTreesAndBuildings) {
  const Terrain terrain(crowdedTerrain());  // several crowns in a small view
  const Camera camera = smallCamera();
  const SurfaceView view(terrain, camera, nadirCameraFromWorld({100.0, 50.0, 45.0}));
  int onSurface = 0, onObstacle = 0, total = 0;
  for (int v = 0; v < camera.height; v += 6) {
    for (int u = 0; u < camera.width; u += 6) {
      const SurfaceHit hit = view.hit(u, v);
      onSurface += std::abs(hit.point.z() - terrain.height(hit.point.x(), hit.point.y())) < 0.01;
      onObstacle += hit.tree != nullptr || hit.building != nullptr;
      ++total;
    }
  }
  EXPECT_GT(onObstacle, total / 10);  // the check sees crowns and roofs, not just ground
  // Off the surface: only walls and the sides of crowns seen obliquely (the heightfield's vertical faces).
  EXPECT_GT(onSurface, 0.97 * total);
}

// The renderer's row path traces what hit() traces, pixel by pixel, over
// rows cut into segments of any length.
TEST(SurfaceViewRows, HitRowGivesWhatHitGives) {
  const Terrain terrain(crowdedTerrain());
  const Camera camera = smallCamera();
  const SurfaceView view(terrain, camera, obliqueCameraFromWorld());
  RowHits row;
  int compared = 0, onObstacles = 0, otherwise = 0;
  double worstPoint = 0.0, worstFootprint = 0.0;
  for (int v = 0; v < camera.height; v += 3) {
    for (int first = 0; first < camera.width;) {
      const int count = std::min(camera.width - first, 1 + (v + first) % 53);  // segments of 1-53 pixels
      view.hitRow(v, first, count, row);
      ASSERT_EQ(row.size(), count);
      for (int k = 0; k < count; ++k) {
        const SurfaceHit exact = view.hit(first + k, v), traced = row.hit(k);
        ++compared;
        if (exact.tree != traced.tree || exact.building != traced.building) {
          ++otherwise;
          continue;
        }
        onObstacles += exact.tree != nullptr || exact.building != nullptr;
        worstPoint = std::max(worstPoint, (exact.point - traced.point).norm());
        worstFootprint = std::max(worstFootprint, std::abs(row.footprintAt(k) / view.footprint(exact) - 1.0));
      }
      first += count;
    }
  }
  EXPECT_GT(onObstacles, compared / 10);
  // A ray grazing a crown's rim, where it meets the ground, may tip either way by rounding.
  EXPECT_LE(otherwise, compared / 10000) << "of " << compared;
  EXPECT_LT(worstPoint, 1e-6);  // metres, 45 m away
  // The footprint's factor for the ray's direction is interpolated across 16-pixel cells, an error that falls with
  // the square of a cell's angle; at this camera's 417 px focal length it is printed (docs/simulator.md quotes it).
  std::printf("hitRow against hit(): worst point %.2e m, worst footprint %.2e relative, %d of %d pixels differ\n",
              worstPoint, worstFootprint, otherwise, compared);
  EXPECT_LT(worstFootprint, 1e-3);
}

// Every ground hit of a view lies inside one of its ground regions, with its
// footprint inside that region's range: what the texture caches for an image.
// That includes the ground under crowns and roofs, which the renderer samples too.
TEST(SurfaceViewRows, GroundRegionsHoldEveryGroundHit) {
  const Terrain terrain(crowdedTerrain());
  const Camera camera = smallCamera();
  const SurfaceView view(terrain, camera, obliqueCameraFromWorld());
  const std::vector<TexelRegion> regions = view.groundRegions();
  ASSERT_FALSE(regions.empty());
  RowHits row;
  int outside = 0;
  for (int v = 0; v < camera.height; ++v) {
    view.hitRow(v, 0, camera.width, row);
    for (int u = 0; u < camera.width; ++u) {
      const bool held = std::any_of(regions.begin(), regions.end(), [&](const TexelRegion& r) {
        return r.box.contains(Eigen::Vector2d(row.x[u], row.y[u])) && row.footprint_m[u] >= r.minFootprint_m &&
               row.footprint_m[u] <= r.maxFootprint_m;
      });
      outside += !held;
    }
  }
  EXPECT_EQ(outside, 0);
}

// Every crown hit of a view, in a crowded wood seen obliquely, lies inside
// the region of its crown, with its footprint inside that region's range.
TEST(SurfaceViewRows, CrownRegionsHoldEveryCrownHit) {
  const Terrain terrain(crowdedTerrain());
  const Camera camera = smallCamera();
  const SurfaceView view(terrain, camera, obliqueCameraFromWorld());
  const std::vector<TexelRegion>& regions = view.crownRegions();
  ASSERT_FALSE(regions.empty());
  RowHits row;
  int crownHits = 0, outside = 0;
  for (int v = 0; v < camera.height; ++v) {
    view.hitRow(v, 0, camera.width, row);
    for (const RowHits::Obstacle& obstacle : row.obstacles) {
      if (obstacle.hit.tree == nullptr) continue;
      ++crownHits;
      const bool held = std::any_of(regions.begin(), regions.end(), [&](const TexelRegion& r) {
        return r.box.contains(obstacle.hit.point.head<2>()) && obstacle.footprint_m >= r.minFootprint_m &&
               obstacle.footprint_m <= r.maxFootprint_m;
      });
      outside += !held;
    }
  }
  EXPECT_GT(crownHits, camera.width * camera.height / 20);  // the wood fills a good part of the view
  EXPECT_EQ(outside, 0);
}

// Rows are shaded and noised in parallel bands: the image does not depend on the number of threads.
TEST(ImageRenderer, ImageDoesNotDependOnTheThreads) {
  const Terrain terrain(crowdedTerrain());
  const GroundTexture texture(GroundTextureOptions{});
  RenderOptions one, two;
  one.threads = 1, two.threads = 2;
  const Camera camera = smallCamera();
  const cv::Mat a = ImageRenderer(terrain, texture, one, 5).render(camera, obliqueCameraFromWorld(), 2.0, 60, 1);
  const cv::Mat b = ImageRenderer(terrain, texture, two, 5).render(camera, obliqueCameraFromWorld(), 2.0, 60, 1);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
}

TEST(ImageRenderer, SameSeedGivesTheSameImageAndAnotherSeedAnother) {
  const Terrain terrain(TerrainOptions{});
  const GroundTexture texture(GroundTextureOptions{});
  const Camera camera = smallCamera();
  const Eigen::Isometry3d pose = nadirCameraFromWorld({0.0, 0.0, 60.0});
  const RenderOptions options;
  const cv::Mat a = ImageRenderer(terrain, texture, options, 7).render(camera, pose, 1.0, 30, 0);
  const cv::Mat b = ImageRenderer(terrain, texture, options, 7).render(camera, pose, 1.0, 30, 0);
  const cv::Mat c = ImageRenderer(terrain, texture, options, 8).render(camera, pose, 1.0, 30, 0);
  GroundTextureOptions otherLook;
  otherLook.seed = 2;
  const GroundTexture otherTexture(otherLook);
  const cv::Mat d = ImageRenderer(terrain, otherTexture, options, 7).render(camera, pose, 1.0, 30, 0);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_L1) / a.total(), 1.0);   // new sensor noise
  EXPECT_GT(cv::norm(a, d, cv::NORM_L1) / a.total(), 10.0);  // another landscape
}

TEST(ImageRenderer, SensorNoiseHasTheRequestedSigma) {
  const Terrain terrain(flatTerrain());
  const ConstantTexture texture;
  const Camera camera = smallCamera();
  const Eigen::Isometry3d pose = nadirCameraFromWorld({0.0, 0.0, 60.0});
  RenderOptions noisy = sceneOnly();
  noisy.noiseSigma_grey = 4.0;
  const cv::Mat clean = ImageRenderer(terrain, texture, sceneOnly(), 1).render(camera, pose, 0.0, 0, 0);
  const cv::Mat image = ImageRenderer(terrain, texture, noisy, 1).render(camera, pose, 0.0, 0, 0);
  cv::Mat difference;
  cv::subtract(image, clean, difference, cv::noArray(), CV_64F);
  cv::Scalar mean, sigma;
  cv::meanStdDev(difference, mean, sigma);
  // Rounding to integers adds 1/12 grey level^2 of variance.
  EXPECT_NEAR(sigma[0], std::sqrt(16.0 + 1.0 / 12.0), 0.1);
  EXPECT_NEAR(mean[0], 0.0, 0.05);
}

TEST(ImageRenderer, ExposureDriftStaysWithinItsAmplitudeAndVaries) {
  const Terrain terrain(flatTerrain());
  const ConstantTexture texture;
  RenderOptions options;
  options.exposureDrift = 0.1;
  const ImageRenderer renderer(terrain, texture, options, 1);
  double low = 2.0, high = 0.0;
  for (double t = 0.0; t < 120.0; t += 0.5) {
    low = std::min(low, renderer.gain(t, 0));
    high = std::max(high, renderer.gain(t, 0));
  }
  EXPECT_GE(low, 0.9);
  EXPECT_LE(high, 1.1);
  EXPECT_GT(high - low, 0.05);
  EXPECT_NE(renderer.gain(3.0, 0), renderer.gain(3.0, 1));  // each camera drifts on its own
}

TEST(ImageRenderer, FarmlandIsTexturedEverywhereForCornerDetectors) {
  const Terrain terrain(TerrainOptions{});
  const GroundTexture texture(GroundTextureOptions{});
  // The centre 320 x 240 of the paper's 1280 x 960 camera: the same ground resolution (2-7 cm per pixel).
  Camera camera = paperRig().cameras[0];
  camera.width = 320, camera.height = 240, camera.intrinsics.cx = 160.0, camera.intrinsics.cy = 120.0;
  for (double height : {30.0, 120.0}) {
    for (double x : {0.0, 400.0, 800.0}) {
      const cv::Mat image = ImageRenderer(terrain, texture, RenderOptions{}, 1)
                                .render(camera, nadirCameraFromWorld({x, 0.0, height}), 0.0, 0, 0);
      std::vector<cv::Point2f> corners;
      cv::goodFeaturesToTrack(image, corners, 2000, 0.01, 10.0);
      EXPECT_GT(corners.size(), 100u) << "at " << height << " m over x = " << x;
      // Textured everywhere: each of 4 x 4 cells of the image has corners.
      int cells[16] = {};
      for (const cv::Point2f& p : corners)
        ++cells[static_cast<int>(4 * p.x / camera.width) + 4 * static_cast<int>(4 * p.y / camera.height)];
      for (int count : cells) EXPECT_GE(count, 3) << "at " << height << " m over x = " << x;
    }
  }
}

TEST(SimScenario, YamlRoundTripKeepsEverySetting) {
  SimScenario s = paperScenario();
  s.name = "round trip";
  s.seed = 12345678901234ULL;
  s.flight.frameStep = 3;
  s.terrain.treeHeight_m = 9.5;
  s.rig = paperRig(0.5, 640, 480);
  s.rig.extrinsics[0] << 0.5, 0.001, -0.002, 0.003, -0.004, 0.005;
  s.deformation.offset << 1e-4, 2e-4, 3e-4, 1e-3, 2e-3, 3e-3;
  s.texture.fieldSize_m = 80.0;
  s.render.blurSigma_px = 0.8;
  s.render.threads = 1;
  const std::string path = (std::filesystem::temp_directory_path() / "lrsvo_scenario_round_trip.yaml").string();
  writeScenarioYaml(s, path);
  const SimScenario r = loadScenario(path);
  EXPECT_EQ(r.name, s.name);
  EXPECT_EQ(r.seed, s.seed);
  EXPECT_EQ(r.flight.frameStep, 3);
  ASSERT_EQ(r.flight.legs.size(), s.flight.legs.size());
  for (std::size_t i = 0; i < s.flight.legs.size(); ++i) {
    EXPECT_EQ(r.flight.legs[i].kind, s.flight.legs[i].kind);
    EXPECT_DOUBLE_EQ(r.flight.legs[i].length_m, s.flight.legs[i].length_m);
    EXPECT_DOUBLE_EQ(r.flight.legs[i].turnRate_rad_s, s.flight.legs[i].turnRate_rad_s);
    EXPECT_DOUBLE_EQ(r.flight.legs[i].climbRate_m_s, s.flight.legs[i].climbRate_m_s);
  }
  EXPECT_DOUBLE_EQ(r.flight.attitudeNoise_rad, s.flight.attitudeNoise_rad);
  EXPECT_DOUBLE_EQ(r.terrain.treeHeight_m, 9.5);
  ASSERT_EQ(r.rig.cameras.size(), 2u);
  EXPECT_EQ(r.rig.cameras[1].width, 640);
  EXPECT_DOUBLE_EQ(r.rig.cameras[1].intrinsics.fx, s.rig.cameras[1].intrinsics.fx);
  EXPECT_TRUE(r.rig.extrinsics[0].isApprox(s.rig.extrinsics[0], 1e-15));
  EXPECT_TRUE(r.deformation.drift.isApprox(s.deformation.drift, 1e-15));
  EXPECT_TRUE(r.deformation.offset.isApprox(s.deformation.offset, 1e-15));
  EXPECT_DOUBLE_EQ(r.texture.fieldSize_m, 80.0);
  EXPECT_DOUBLE_EQ(r.render.blurSigma_px, 0.8);
  EXPECT_EQ(r.render.threads, 1);
  std::filesystem::remove(path);
}

TEST(SimScenario, YamlKeysAreOptionalAndUnknownKeysAreNamed) {
  const std::string path = (std::filesystem::temp_directory_path() / "lrsvo_scenario_keys.yaml").string();
  std::ofstream(path) << "%YAML:1.0\nbase: paper\nflight:\n  altitude_m: 80\n";
  const SimScenario s = loadScenario(path);
  EXPECT_DOUBLE_EQ(s.flight.altitude_m, 80.0);
  EXPECT_EQ(s.flight.legs.size(), paperScenario().flight.legs.size());  // the rest from the base
  std::ofstream(path) << "%YAML:1.0\nflight:\n  altitude_m: 80\n  altitud_m: 3\n";
  try {
    loadScenario(path);
    FAIL() << "an unknown key must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("altitud_m"), std::string::npos) << e.what();
  }
  std::ofstream(path) << "%YAML:1.0\nrender: {noiseSigma_grey: loud}\n";
  EXPECT_THROW(loadScenario(path), Error);
  std::filesystem::remove(path);
  EXPECT_THROW(loadScenario("nowhere"), Error);
}

TEST(SimScenario, PaperFlightSpansThirtyToOneHundredTwentyMetresAboveTheTerrain) {
  const SimScenario s = paperScenario();
  const Terrain terrain(s.terrain);
  const FlightTruth truth = simulateFlightTruth(s.flight, terrain, s.rig, s.deformation);
  ASSERT_EQ(truth.times_s.size(), 9600u);
  double low = 1e9, high = -1e9, length = 0.0, clearance = 1e9;
  Eigen::Vector3d previous = truth.cameraFromWorld[0].inverse().translation();
  for (std::size_t i = 0; i < truth.times_s.size(); ++i) {
    const Eigen::Vector3d centre = truth.cameraFromWorld[i].inverse().translation();
    low = std::min(low, centre.z());
    high = std::max(high, centre.z());
    clearance = std::min(clearance, centre.z() - terrain.height(centre.x(), centre.y()));
    length += (centre - previous).norm();
    previous = centre;
    const Vector6 change = truth.extrinsics[i][0] - s.rig.extrinsics[0];
    ASSERT_LE(change.head<3>().cwiseAbs().maxCoeff(), 1e-3) << "frame " << i;
    ASSERT_LE(change.tail<3>().cwiseAbs().maxCoeff(), 0.01) << "frame " << i;
  }
  EXPECT_GE(low, 30.0);
  EXPECT_LE(high, 120.0);
  EXPECT_GT(high - low, 70.0);
  EXPECT_GT(clearance, 10.0);
  EXPECT_NEAR(length, 6400.0, 50.0);
}

SimScenario tinyScenario() {
  SimScenario s = demoScenario();
  s.rig = paperRig(0.7, 160, 120);
  s.flight.legs = {{FlightLeg::Kind::Straight, 2.0}};  // 0.1 s: 4 frames at 30 Hz
  s.render.threads = 1;
  return s;
}

TEST(SimFrameSource, DeliversEveryFrameWithItsTimeAndTheTruth) {
  SimFrameSource source(tinyScenario());
  ASSERT_EQ(source.frameCount(), 4);
  EXPECT_EQ(source.name(), "sim:demo");
  ASSERT_EQ(source.distortion().size(), 2u);
  EXPECT_TRUE(source.distortion()[1].none());
  const GroundTruth truth = source.groundTruth();
  ASSERT_EQ(truth.poses.size(), 4u);
  ASSERT_EQ(truth.extrinsics.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const std::optional<StereoFrame> frame = source.next();
    ASSERT_TRUE(frame.has_value());
    EXPECT_EQ(frame->index, i);
    EXPECT_DOUBLE_EQ(frame->time_s, i / 30.0);
    EXPECT_DOUBLE_EQ(truth.poses[i].time_s, i / 30.0);
    ASSERT_EQ(frame->cameraCount(), 2);
    EXPECT_EQ(frame->images[0].type(), CV_8UC1);
    // The secondary image is rendered when first asked for, then kept; it is
    // the image render() gives.
    ASSERT_TRUE(frame->deferred);
    EXPECT_TRUE(frame->images[1].empty());
    EXPECT_FALSE(frame->deferred->made(1));
    const cv::Mat& secondary = frame->image(1);
    EXPECT_TRUE(frame->deferred->made(1));
    EXPECT_EQ(secondary.size(), cv::Size(160, 120));
    EXPECT_EQ(frame->image(1).data, secondary.data);
    EXPECT_EQ(cv::norm(secondary, source.render(i).images[1], cv::NORM_INF), 0.0);
    EXPECT_THROW(frame->image(2), Error);
    // 100 m up, 20 m/s along world x.
    EXPECT_NEAR(truth.poses[i].worldFromCamera.translation().x(), 20.0 * i / 30.0, 1e-6);
    EXPECT_NEAR(truth.poses[i].worldFromCamera.translation().z(), 100.0, 1e-6);
    EXPECT_TRUE(truth.poses[i].worldFromCamera.isApprox(source.truth().cameraFromWorld[i].inverse(), 1e-12));
    EXPECT_LT((truth.extrinsics[i][0] - source.rig().extrinsics[0]).cwiseAbs().maxCoeff(), 0.01);
    EXPECT_GT(cv::norm(frame->images[0], secondary, cv::NORM_L1), 0.0);
  }
  EXPECT_FALSE(source.next().has_value());
  EXPECT_THROW(source.render(4), Error);

  SimFrameSource skipping(tinyScenario());
  skipping.skip(2);  // seeks: frames 0 and 1 are never rendered
  const std::optional<StereoFrame> third = skipping.next();
  ASSERT_TRUE(third.has_value());
  EXPECT_EQ(third->index, 2);
  EXPECT_EQ(cv::norm(third->images[0], source.render(2).images[0], cv::NORM_INF), 0.0);
  skipping.skip(5);
  EXPECT_FALSE(skipping.next().has_value());
}

TEST(SimFrameSource, EurocWriterLaysOutImagesCalibrationAndTruth) {
  const SimFrameSource source(tinyScenario());
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lrsvo_euroc_writer";
  std::filesystem::remove_all(dir);
  {
    EurocWriter writer(dir.string(), source.rig(), 30.0);
    for (int i = 0; i < 2; ++i)
      writer.write(source.render(i), source.truth().cameraFromWorld[i].inverse(), source.truth().extrinsics[i]);
  }
  const cv::Mat image = cv::imread((dir / "mav0/cam1/data/33333333.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.size(), cv::Size(160, 120));
  auto lines = [](const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    return all;
  };
  const std::vector<std::string> csv = lines(dir / "mav0/cam0/data.csv");
  ASSERT_EQ(csv.size(), 3u);
  EXPECT_EQ(csv[0], "#timestamp [ns],filename");
  EXPECT_EQ(csv[2], "33333333,33333333.png");
  EXPECT_EQ(lines(dir / "groundtruth_cam0_tum.txt").size(), 3u);
  EXPECT_EQ(lines(dir / "true_extrinsics.csv").size(), 3u);
  // cam1's T_BS is body(cam0)-from-cam1: with the rig along x, its translation is (0.7, 0, 0).
  std::ifstream sensor(dir / "mav0/cam1/sensor.yaml");
  const std::string text((std::istreambuf_iterator<char>(sensor)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("data: [1, 0, 0, 0.7,"), std::string::npos) << text;
  EXPECT_NE(text.find("resolution: [160, 120]"), std::string::npos);
  EXPECT_NE(text.find("distortion_coefficients: [0.0, 0.0, 0.0, 0.0]"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lrsvo
