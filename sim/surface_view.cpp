#include "lrsvo/sim/surface_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/sim/footprint.h"

namespace lrsvo {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();
constexpr int kMaxNewtonSteps = 30;

// Depth at which the ray first enters the upper half of a crown ellipsoid, or kNone.
// The crown is given as the view's CrownFromCentre: scale, q0 and c.
double crownDepth(const Eigen::Vector3d& scale, const Eigen::Vector3d& q0, double c, const Eigen::Vector3d& direction) {
  const Eigen::Vector3d qd = direction.cwiseProduct(scale);
  const double a = qd.squaredNorm(), b = q0.dot(qd);
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return kNone;
  const double t = (-b - std::sqrt(discriminant)) / a;
  return t > 0.0 && q0.z() + t * qd.z() >= 0.0 ? t : kNone;
}

// Depth at which the ray from `origin` enters the building's box (footprint x (-inf, roof]), or kNone.
double buildingDepth(const Eigen::Vector3d& origin, const std::array<double, 2>& start,
                     const Eigen::Vector3d& direction, const Terrain::Building& b) {
  const std::array<double, 2> step = {b.cosHeading * direction.x() + b.sinHeading * direction.y(),
                                      -b.sinHeading * direction.x() + b.cosHeading * direction.y()};
  double enter = -kNone, exit = kNone;
  for (int axis = 0; axis < 2; ++axis) {
    const double half = b.halfSize[axis];
    if (step[axis] == 0.0) {
      if (std::abs(start[axis]) > half) return kNone;
      continue;
    }
    const double t1 = (-half - start[axis]) / step[axis], t2 = (half - start[axis]) / step[axis];
    enter = std::max(enter, std::min(t1, t2));
    exit = std::min(exit, std::max(t1, t2));
  }
  if (direction.z() < 0.0)
    enter = std::max(enter, (b.roof - origin.z()) / direction.z());
  else if (origin.z() > b.roof)
    return kNone;
  return enter < exit && enter > 0.0 ? enter : kNone;
}

// One row's ground hits across one cell of the ground grid: the depth, the ray and the footprint per unit
// depth at the cell's left side, and their steps per pixel.
struct GroundSteps {
  double depth, depthStep, scale, scaleStep;
  Eigen::Vector3d ray, rayStep, centre;
};

// The ground hit and footprint `step` .. step + count - 1 pixels right of the cell's left side, into x, y, z
// and footprint[0 .. count - 1]. Built for AVX2 too, picked at run time: the same operations, four pixels at a
// time (no fused multiply-adds either way, so the same values).
__attribute__((target_clones("avx2", "default"))) void stepGround(const GroundSteps& g, int step, int count, double* x,
                                                                  double* y, double* z, float* footprint) {
  for (int n = 0; n < count; ++n) {
    const double steps = step + n;
    const double depth = g.depth + steps * g.depthStep;
    x[n] = g.centre.x() + depth * (g.ray.x() + steps * g.rayStep.x());
    y[n] = g.centre.y() + depth * (g.ray.y() + steps * g.rayStep.y());
    z[n] = g.centre.z() + depth * (g.ray.z() + steps * g.rayStep.z());
    footprint[n] = static_cast<float>(depth * (g.scale + steps * g.scaleStep));
  }
}

}  // namespace

SurfaceView::SurfaceView(const Terrain& terrain, const Camera& camera, const Eigen::Isometry3d& cameraFromWorld,
                         int threads)
    : terrain_(terrain),
      camera_(camera),
      meanFocal_(std::sqrt(camera.intrinsics.fx * camera.intrinsics.fy)),
      cameraFromWorld_(cameraFromWorld) {
  const Eigen::Isometry3d worldFromCamera = cameraFromWorld.inverse();
  worldFromCameraRotation_ = worldFromCamera.linear();
  centre_ = worldFromCamera.translation();
  groundBelowCentre_ = terrain.groundHeight(centre_.x(), centre_.y());
  nodesU_ = (camera.width - 1 + kGroundGrid_px - 1) / kGroundGrid_px + 1;
  nodesV_ = (camera.height - 1 + kGroundGrid_px - 1) / kGroundGrid_px + 1;
  solveGroundGrid(threads);
  listObstacles(terrain.minHeight() - 1.0);
}

void SurfaceView::solveGroundGrid(int threads) {
  groundDepth_.resize(static_cast<std::size_t>(nodesU_) * nodesV_);
  footprintPerDepth_.resize(groundDepth_.size());
  // An exception must not leave a parallel region: each row keeps its own, the first is rethrown.
  std::vector<std::exception_ptr> failures(nodesV_);
  parallelFor(0, nodesV_, threads, 1, [&](int j) {
    try {
      for (int i = 0; i < nodesU_; ++i) {
        const Eigen::Vector3d direction = ray(i * kGroundGrid_px, j * kGroundGrid_px);
        groundDepth_[j * nodesU_ + i] = groundDepth(direction);
        footprintPerDepth_[j * nodesU_ + i] = footprintAlong(direction);
      }
    } catch (...) {
      failures[j] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

std::vector<TexelRegion> SurfaceView::groundRegions() const {
  constexpr double kFootprintMargin = 0.01;
  std::vector<Eigen::Vector2d> nodes(groundDepth_.size());
  std::vector<double> footprints(groundDepth_.size());
  for (int j = 0; j < nodesV_; ++j) {
    for (int i = 0; i < nodesU_; ++i) {
      const std::size_t n = static_cast<std::size_t>(j) * nodesU_ + i;
      nodes[n] = (centre_ + groundDepth_[n] * ray(i * kGroundGrid_px, j * kGroundGrid_px)).head<2>();
      footprints[n] = groundDepth_[n] * footprintPerDepth_[n];
    }
  }
  std::vector<TexelRegion> regions;
  regions.reserve(static_cast<std::size_t>(nodesU_ - 1) * (nodesV_ - 1));
  for (int j = 0; j + 1 < nodesV_; ++j) {
    for (int i = 0; i + 1 < nodesU_; ++i) {
      TexelRegion region;
      double low = std::numeric_limits<double>::infinity(), high = 0.0;
      const int corner = j * nodesU_ + i;
      for (const int n : {corner, corner + 1, corner + nodesU_, corner + nodesU_ + 1}) {
        region.box.extend(nodes[n]);
        low = std::min(low, footprints[n]), high = std::max(high, footprints[n]);
      }
      region.box.min().array() -= high;
      region.box.max().array() += high;
      region.minFootprint_m = static_cast<float>(low * (1.0 - kFootprintMargin));
      region.maxFootprint_m = static_cast<float>(high * (1.0 + kFootprintMargin));
      regions.push_back(region);
    }
  }
  return regions;
}

inline Eigen::Vector3d SurfaceView::ray(double u, double v) const {
  const PinholeIntrinsics& k = camera_.intrinsics;
  return worldFromCameraRotation_ * Eigen::Vector3d((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
}

double SurfaceView::groundDepth(const Eigen::Vector3d& direction) const {
  if (!(direction.z() < 0.0))
    throw Error("surface view: a camera ray does not point down (the camera at z = " + std::to_string(centre_.z()) +
                " m sees the horizon); keep bank and pitch well below 90 deg minus half the field of view");
  auto miss = [&](double t) {
    const Eigen::Vector3d p = centre_ + t * direction;
    return p.z() - terrain_.groundHeight(p.x(), p.y());
  };
  double t = (centre_.z() - groundBelowCentre_) / -direction.z();
  for (int step = 0; step < kMaxNewtonSteps; ++step) {
    const double h = 1e-4 * t;
    const double slope = (miss(t + h) - miss(t - h)) / (2.0 * h);
    const double update = miss(t) / slope;
    t -= update;
    if (std::abs(update) < 1e-9 * t) break;
  }
  if (!(t > 0.0 && std::isfinite(t)))
    throw Error("surface view: a camera ray at z = " + std::to_string(centre_.z()) +
                " m does not meet the ground in front of the camera; is the camera below the terrain?");
  return t;
}

inline double SurfaceView::interpolatedGroundDepth(double u, double v) const {
  const double gu = std::clamp(u / kGroundGrid_px, 0.0, nodesU_ - 1.0);
  const double gv = std::clamp(v / kGroundGrid_px, 0.0, nodesV_ - 1.0);
  const int i = std::min(static_cast<int>(gu), nodesU_ - 2), j = std::min(static_cast<int>(gv), nodesV_ - 2);
  const double a = gu - i, b = gv - j;
  const double* row0 = &groundDepth_[j * nodesU_ + i];
  const double* row1 = row0 + nodesU_;
  return (1.0 - b) * ((1.0 - a) * row0[0] + a * row0[1]) + b * ((1.0 - a) * row1[0] + a * row1[1]);
}

void SurfaceView::listObstacles(double bottom) {
  Eigen::AlignedBox2d area(centre_.head<2>());
  for (const Eigen::Vector2d& corner : groundFootprint(camera_, cameraFromWorld_, terrain_.minHeight()))
    area.extend(corner);
  obstacles_ = terrain_.obstaclesIn(area);
  // What every ray from the centre shares, per obstacle: a crown in the coordinates that make it a unit sphere,
  // the centre in a building's own axes.
  crownsFromCentre_.clear();
  for (const Terrain::Tree& t : obstacles_.trees) {
    CrownFromCentre& crown = crownsFromCentre_.emplace_back();
    crown.scale = Eigen::Vector3d(1.0 / t.radius, 1.0 / t.radius, 1.0 / t.height);
    crown.q0 = (centre_ - Eigen::Vector3d(t.centre.x(), t.centre.y(), t.base)).cwiseProduct(crown.scale);
    crown.c = crown.q0.squaredNorm() - 1.0;
  }
  buildingStarts_.clear();
  for (const Terrain::Building& b : obstacles_.buildings) {
    const Eigen::Vector2d p = centre_.head<2>() - b.centre;
    buildingStarts_.push_back(
        {b.cosHeading * p.x() + b.sinHeading * p.y(), -b.sinHeading * p.x() + b.cosHeading * p.y()});
  }
  tilesU_ = (camera_.width + kTile_px - 1) / kTile_px;
  tilesV_ = (camera_.height + kTile_px - 1) / kTile_px;
  tiles_.assign(static_cast<std::size_t>(tilesU_) * tilesV_, {});
  // Each obstacle goes to the tiles its 3D bounding box covers in the image,
  // with the pixels that box covers (one pixel wider on each side).
  auto add = [&](const Eigen::AlignedBox3d& box, int id) {
    Eigen::AlignedBox2d image;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d p = cameraFromWorld_ * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
      if (p.z() <= 1e-6) {  // behind or beside the camera: every tile
        image = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(camera_.width, camera_.height));
        break;
      }
      image.extend(camera_.intrinsics.project(p));
    }
    const Eigen::Vector2d low = image.min().array() - 1.0, high = image.max().array() + 1.0;
    if (high.x() < 0.0 || high.y() < 0.0 || low.x() > camera_.width - 1 || low.y() > camera_.height - 1) return;
    // Clamped into the image before the conversion: a corner just in front of the camera projects far outside.
    auto pixel = [](double x, int last) { return std::clamp(x, 0.0, static_cast<double>(last)); };
    const ObstacleSpan span{id, static_cast<int>(std::floor(pixel(low.x(), camera_.width - 1))),
                            static_cast<int>(std::ceil(pixel(high.x(), camera_.width - 1))),
                            static_cast<int>(std::floor(pixel(low.y(), camera_.height - 1))),
                            static_cast<int>(std::ceil(pixel(high.y(), camera_.height - 1)))};
    for (int tv = span.v0 / kTile_px; tv <= span.v1 / kTile_px; ++tv)
      for (int tu = span.u0 / kTile_px; tu <= span.u1 / kTile_px; ++tu) tile(tu, tv).push_back(span);
    if (id >= 0) crownRegions_.push_back(regionOver(box));
  };
  for (std::size_t i = 0; i < obstacles_.trees.size(); ++i) {
    const Terrain::Tree& t = obstacles_.trees[i];
    add(Eigen::AlignedBox3d(Eigen::Vector3d(t.centre.x() - t.radius, t.centre.y() - t.radius, t.base),
                            Eigen::Vector3d(t.centre.x() + t.radius, t.centre.y() + t.radius, t.base + t.height)),
        static_cast<int>(i));
  }
  for (std::size_t i = 0; i < obstacles_.buildings.size(); ++i) {
    const Terrain::Building& b = obstacles_.buildings[i];
    const double reach = b.halfSize.norm();
    add(Eigen::AlignedBox3d(Eigen::Vector3d(b.centre.x() - reach, b.centre.y() - reach, bottom),
                            Eigen::Vector3d(b.centre.x() + reach, b.centre.y() + reach, b.roof)),
        -1 - static_cast<int>(i));
  }
}

TexelRegion SurfaceView::regionOver(const Eigen::AlignedBox3d& box) const {
  constexpr double kFootprintMargin = 0.01;
  // footprintAlong(): range / focal / sqrt(obliquity), the obliquity at most 1
  // and at least the box's nearest height difference over its farthest range.
  double farthest = 0.0;
  for (int c = 0; c < 8; ++c)
    farthest = std::max(farthest, (box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - centre_).norm());
  const double nearestHeight = std::max({0.0, box.min().z() - centre_.z(), centre_.z() - box.max().z()});
  const double obliquity = std::max(0.25, nearestHeight / farthest);
  TexelRegion region;
  region.box = Eigen::AlignedBox2d(box.min().head<2>(), box.max().head<2>());
  region.minFootprint_m = static_cast<float>(box.exteriorDistance(centre_) / meanFocal_ * (1.0 - kFootprintMargin));
  region.maxFootprint_m = static_cast<float>(farthest / meanFocal_ / std::sqrt(obliquity) * (1.0 + kFootprintMargin));
  return region;
}

bool SurfaceView::meets(int id, const Eigen::Vector3d& direction, double& depth, SurfaceHit& hit) const {
  if (id >= 0) {
    const CrownFromCentre& crown = crownsFromCentre_[id];
    const double t = crownDepth(crown.scale, crown.q0, crown.c, direction);
    if (!(t < depth)) return false;
    depth = t, hit.tree = &obstacles_.trees[id], hit.building = nullptr;
  } else {
    const double t = buildingDepth(centre_, buildingStarts_[-1 - id], direction, obstacles_.buildings[-1 - id]);
    if (!(t < depth)) return false;
    depth = t, hit.building = &obstacles_.buildings[-1 - id], hit.tree = nullptr;
  }
  hit.point = centre_ + depth * direction;
  return true;
}

SurfaceHit SurfaceView::hit(double u, double v) const {
  const Eigen::Vector3d direction = ray(u, v);
  double depth = interpolatedGroundDepth(u, v);
  SurfaceHit hit;
  hit.point = centre_ + depth * direction;
  const int tu = std::clamp(static_cast<int>(std::floor(u / kTile_px)), 0, tilesU_ - 1);
  const int tv = std::clamp(static_cast<int>(std::floor(v / kTile_px)), 0, tilesV_ - 1);
  for (const ObstacleSpan& span : tiles_[tv * tilesU_ + tu])
    if (u >= span.u0 - 0.5 && u <= span.u1 + 0.5 && v >= span.v0 - 0.5 && v <= span.v1 + 0.5)
      meets(span.id, direction, depth, hit);
  return hit;
}

void SurfaceView::hitRow(int v, int first, int count, RowHits& row) const {
  row.reset(count);
  const int end = first + count;
  const double gv = std::clamp(static_cast<double>(v) / kGroundGrid_px, 0.0, nodesV_ - 1.0);
  const int j = std::min(static_cast<int>(gv), nodesV_ - 2);
  const double b = gv - j;
  auto inRow = [&](const std::vector<double>& nodeValues, int i) {
    return (1.0 - b) * nodeValues[j * nodesU_ + i] + b * nodeValues[(j + 1) * nodesU_ + i];
  };
  const Eigen::Vector3d rayStep = worldFromCameraRotation_.col(0) / camera_.intrinsics.fx;
  for (int u = first; u < end;) {
    // The cell of pixel u (the last cell also holds a pixel on the grid's last node): ground depth, ray and
    // footprint per unit depth at its left side in this row, and their steps along u.
    const int i = std::min(u / kGroundGrid_px, nodesU_ - 2), left = i * kGroundGrid_px;
    const int cellEnd = i == nodesU_ - 2 ? end : std::min(end, left + kGroundGrid_px);
    const double depthLeft = inRow(groundDepth_, i);
    const double depthStep = (inRow(groundDepth_, i + 1) - depthLeft) / kGroundGrid_px;
    const double scaleLeft = inRow(footprintPerDepth_, i);
    const double scaleStep = (inRow(footprintPerDepth_, i + 1) - scaleLeft) / kGroundGrid_px;
    const Eigen::Vector3d rayLeft = ray(left, v);
    const GroundSteps steps{depthLeft, depthStep, scaleLeft, scaleStep, rayLeft, rayStep, centre_};
    const int k = u - first;
    stepGround(steps, u - left, cellEnd - u, &row.x[k], &row.y[k], &row.z[k], &row.footprint_m[k]);
    u = cellEnd;
  }
  // Then each obstacle over the pixels of its span in this row, tile by tile (a pixel lies in one tile).
  const int tv = std::min(v / kTile_px, tilesV_ - 1);
  for (int tu = first / kTile_px; tu <= std::min((end - 1) / kTile_px, tilesU_ - 1); ++tu) {
    for (const ObstacleSpan& span : tiles_[tv * tilesU_ + tu]) {
      if (v < span.v0 || v > span.v1) continue;
      const int from = std::max({first, tu * kTile_px, span.u0}),
                to = std::min({end - 1, tu * kTile_px + kTile_px - 1, span.u1});
      for (int u = from; u <= to; ++u) {
        const Eigen::Vector3d direction = ray(u, v);
        const int k = u - first;
        SurfaceHit hit = row.hit(k);  // the ground, or a nearer obstacle
        double depth = (hit.point.z() - centre_.z()) / direction.z();
        if (!meets(span.id, direction, depth, hit)) continue;
        const RowHits::Obstacle nearer{k, hit, static_cast<float>(footprint(hit))};
        int& at = row.obstacleAt[k];
        if (at >= 0)
          row.obstacles[at] = nearer;
        else
          at = static_cast<int>(row.obstacles.size()), row.obstacles.push_back(nearer);
      }
    }
  }
}

double SurfaceView::footprintAlong(const Eigen::Vector3d& toHit) const {
  const double range = toHit.norm();
  const double obliquity = std::max(0.25, std::abs(toHit.z()) / range);  // cosine of the incidence on level ground
  return range / meanFocal_ / std::sqrt(obliquity);
}

double SurfaceView::footprint(const SurfaceHit& hit) const { return footprintAlong(hit.point - centre_); }

}  // namespace lrsvo
