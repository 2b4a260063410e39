#include "sim/surface_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "graph/error.h"
#include "sim/footprint.h"

namespace lrsvo {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();
constexpr int kMaxNewtonSteps = 30;

// Depth at which the ray first enters the upper half of the tree's crown ellipsoid, or kNone.
double crownDepth(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Terrain::Tree& tree) {
  const Eigen::Vector3d scale(1.0 / tree.radius, 1.0 / tree.radius, 1.0 / tree.height);
  const Eigen::Vector3d q0 =
      (origin - Eigen::Vector3d(tree.centre.x(), tree.centre.y(), tree.base)).cwiseProduct(scale);
  const Eigen::Vector3d qd = direction.cwiseProduct(scale);
  const double a = qd.squaredNorm(), b = q0.dot(qd), c = q0.squaredNorm() - 1.0;
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return kNone;
  const double t = (-b - std::sqrt(discriminant)) / a;
  return t > 0.0 && q0.z() + t * qd.z() >= 0.0 ? t : kNone;
}

// Depth at which the ray enters the building's box (footprint x (-inf, roof]), or kNone.
double buildingDepth(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Terrain::Building& b) {
  const Eigen::Vector2d p = origin.head<2>() - b.centre;
  const std::array<double, 2> start = {b.cosHeading * p.x() + b.sinHeading * p.y(),
                                       -b.sinHeading * p.x() + b.cosHeading * p.y()};
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

}  // namespace

SurfaceView::SurfaceView(const Terrain& terrain, const Camera& camera, const Eigen::Isometry3d& cameraFromWorld)
    : terrain_(terrain),
      camera_(camera),
      meanFocal_(std::sqrt(camera.intrinsics.fx * camera.intrinsics.fy)),
      cameraFromWorld_(cameraFromWorld) {
  const Eigen::Isometry3d worldFromCamera = cameraFromWorld.inverse();
  worldFromCameraRotation_ = worldFromCamera.linear();
  centre_ = worldFromCamera.translation();
  nodesU_ = (camera.width - 1 + kGroundGrid_px - 1) / kGroundGrid_px + 1;
  nodesV_ = (camera.height - 1 + kGroundGrid_px - 1) / kGroundGrid_px + 1;
  groundDepth_.resize(static_cast<std::size_t>(nodesU_) * nodesV_);
  for (int j = 0; j < nodesV_; ++j)
    for (int i = 0; i < nodesU_; ++i)
      groundDepth_[j * nodesU_ + i] = groundDepth(ray(i * kGroundGrid_px, j * kGroundGrid_px));
  listObstacles(terrain.minHeight() - 1.0);
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
  double t = (centre_.z() - terrain_.groundHeight(centre_.x(), centre_.y())) / -direction.z();
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
  tilesU_ = (camera_.width + kTile_px - 1) / kTile_px;
  tilesV_ = (camera_.height + kTile_px - 1) / kTile_px;
  tiles_.assign(static_cast<std::size_t>(tilesU_) * tilesV_, {});
  // Each obstacle goes to the tiles its 3D bounding box covers in the image.
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
    const int u0 = std::max(0, static_cast<int>(std::floor((image.min().x() - 1.0) / kTile_px)));
    const int v0 = std::max(0, static_cast<int>(std::floor((image.min().y() - 1.0) / kTile_px)));
    const int u1 = std::min(tilesU_ - 1, static_cast<int>(std::floor((image.max().x() + 1.0) / kTile_px)));
    const int v1 = std::min(tilesV_ - 1, static_cast<int>(std::floor((image.max().y() + 1.0) / kTile_px)));
    for (int tv = v0; tv <= v1; ++tv)
      for (int tu = u0; tu <= u1; ++tu) tile(tu, tv).push_back(id);
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

SurfaceHit SurfaceView::hit(double u, double v) const {
  const Eigen::Vector3d direction = ray(u, v);
  double depth = interpolatedGroundDepth(u, v);
  SurfaceHit hit;
  const int tu = std::clamp(static_cast<int>(std::floor(u / kTile_px)), 0, tilesU_ - 1);
  const int tv = std::clamp(static_cast<int>(std::floor(v / kTile_px)), 0, tilesV_ - 1);
  for (int id : tiles_[tv * tilesU_ + tu]) {
    if (id >= 0) {
      const double t = crownDepth(centre_, direction, obstacles_.trees[id]);
      if (t < depth) depth = t, hit.tree = &obstacles_.trees[id], hit.building = nullptr;
    } else {
      const double t = buildingDepth(centre_, direction, obstacles_.buildings[-1 - id]);
      if (t < depth) depth = t, hit.building = &obstacles_.buildings[-1 - id], hit.tree = nullptr;
    }
  }
  hit.point = centre_ + depth * direction;
  return hit;
}

double SurfaceView::footprint(const SurfaceHit& hit) const {
  const Eigen::Vector3d toHit = hit.point - centre_;
  const double range = toHit.norm();
  const double obliquity = std::max(0.25, std::abs(toHit.z()) / range);  // cosine of the incidence on level ground
  return range / meanFocal_ / std::sqrt(obliquity);
}

}  // namespace lrsvo
