#include "lrsvo/sim/pose_graph_generator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/edges/edge_se2.h"
#include "lrsvo/edges/edge_se3_quat.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/sim/gaussian_noise.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {

namespace {

// Labels of the seed's streams (mixSeed).
constexpr std::uint64_t kWalkStream = 1;
constexpr std::uint64_t kNoiseStream = 2;

using Pair = std::pair<int, int>;  // (from, to) of a relative-pose measurement

// The true path and what measures it: odometry (k, k + 1) first, then loop closures.
struct Layout {
  std::vector<Eigen::Isometry3d> poses;
  std::vector<Pair> loopClosures;
};

Eigen::Isometry3d makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& position) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = position;
  return pose;
}

// Body x along the direction of travel, body z out of the sphere.
Layout sphereLayout(const PoseGraphOptions& options) {
  const int rings = std::max(2, static_cast<int>(std::lround(std::sqrt(options.poses / 2.0))));
  const int perRing = (options.poses + rings - 1) / rings;
  Layout layout;
  for (int k = 0; k < options.poses; ++k) {
    const int ring = k / perRing, index = k % perRing;
    const double polar = std::numbers::pi * (ring + 0.5) / rings;
    const double azimuth = 2.0 * std::numbers::pi * index / perRing;
    const Eigen::Vector3d out(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                              std::cos(polar));
    const Eigen::Vector3d east(-std::sin(azimuth), std::cos(azimuth), 0.0);
    Eigen::Matrix3d rotation;
    rotation << east, out.cross(east), out;
    layout.poses.push_back(makePose(rotation, options.radius * out));
    if (ring > 0) layout.loopClosures.emplace_back(k - perRing, k);
  }
  return layout;
}

// Body x along the last step; body z up, or along world x for a vertical step.
Eigen::Matrix3d gridRotation(int axis, int sign) {
  const Eigen::Vector3d x = sign * Eigen::Vector3d::Unit(axis);
  const Eigen::Vector3d z = axis == 2 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d rotation;
  rotation << x, z.cross(x), z;
  return rotation;
}

Layout gridLayout(const PoseGraphOptions& options) {
  const int d = options.dimension;
  // A box of about N / 4 cells: the walk returns to most cells several times.
  const int side = std::max(2, static_cast<int>(std::ceil(std::pow(options.poses / 4.0, 1.0 / d))));
  SplitMix64 walk(mixSeed(options.seed, kWalkStream));
  Eigen::Vector3i cell = Eigen::Vector3i::Zero();
  for (int a = 0; a < d; ++a) cell[a] = side / 2;  // the box's centre
  int axis = 0, sign = 1;
  std::unordered_map<long long, int> lastVisit;
  const auto key = [side](const Eigen::Vector3i& c) {
    return (static_cast<long long>(c.z()) * side + c.y()) * side + c.x();
  };
  const auto inside = [&](int a, int s) { return cell[a] + s >= 0 && cell[a] + s < side; };
  Layout layout;
  for (int k = 0; k < options.poses; ++k) {
    if (k > 0) {
      // Straight on half the time when the box allows; otherwise any step that stays inside.
      if (walk() % 2 == 0 || !inside(axis, sign)) {
        do {
          axis = static_cast<int>(walk() % static_cast<std::uint64_t>(d));
          sign = walk() % 2 == 0 ? 1 : -1;
        } while (!inside(axis, sign));
      }
      cell[axis] += sign;
    }
    const auto [visit, first] = lastVisit.try_emplace(key(cell), k);
    if (!first) {
      layout.loopClosures.emplace_back(visit->second, k);
      visit->second = k;
    }
    layout.poses.push_back(makePose(gridRotation(axis, sign), cell.cast<double>()));
  }
  return layout;
}

// Standard normal draws of one seeded stream, in order.
class NoiseStream {
 public:
  explicit NoiseStream(std::uint64_t key) : key_(key) {}
  double next() { return standardNormalDraw(key_, index_++); }
  Eigen::Vector3d next3() {
    const double a = next(), b = next();
    return {a, b, next()};
  }

 private:
  std::uint64_t key_;
  std::uint64_t index_ = 0;
};

// (x, y, heading) of a pose whose rotation is about world z.
Eigen::Vector3d planar(const Eigen::Isometry3d& pose) {
  return {pose.translation().x(), pose.translation().y(), std::atan2(pose.linear()(1, 0), pose.linear()(0, 0))};
}

Eigen::Vector3d compose(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector2d t = a.head<2>() + Eigen::Rotation2Dd(a[2]) * b.head<2>();
  return {t.x(), t.y(), wrapAngle(a[2] + b[2])};
}

Eigen::Vector3d between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector2d t = Eigen::Rotation2Dd(-a[2]) * (b.head<2>() - a.head<2>());
  return {t.x(), t.y(), wrapAngle(b[2] - a[2])};
}

Graph buildPlanar(const Layout& layout, const PoseGraphOptions& options) {
  NoiseStream noise(mixSeed(options.seed, kNoiseStream));
  const Eigen::Matrix3d information =
      Eigen::Vector3d(1.0 / std::pow(options.translationSigma, 2), 1.0 / std::pow(options.translationSigma, 2),
                      1.0 / std::pow(options.rotationSigma, 2))
          .asDiagonal();
  const auto measure = [&](int from, int to) {
    const Eigen::Vector3d truth = between(planar(layout.poses[from]), planar(layout.poses[to]));
    const double dx = noise.next(), dy = noise.next(), dtheta = noise.next();
    return Eigen::Vector3d(truth.x() + options.translationSigma * dx, truth.y() + options.translationSigma * dy,
                           wrapAngle(truth.z() + options.rotationSigma * dtheta));
  };
  Graph graph;
  std::vector<VertexSE2*> vertices;
  const auto addEdge = [&](int from, int to, const Eigen::Vector3d& z) {
    auto edge = std::make_unique<EdgeSE2>();
    edge->setVertex(0, vertices[from]);
    edge->setVertex(1, vertices[to]);
    edge->setMeasurement(z);
    edge->setInformation(information);
    graph.addEdge(std::move(edge));
  };
  Eigen::Vector3d start = planar(layout.poses.front());
  vertices.push_back(graph.addVertex(std::make_unique<VertexSE2>(0, start)));
  std::vector<Eigen::Vector3d> odometry;
  for (std::size_t k = 1; k < layout.poses.size(); ++k) {
    odometry.push_back(measure(static_cast<int>(k) - 1, static_cast<int>(k)));
    start = compose(start, odometry.back());
    vertices.push_back(graph.addVertex(std::make_unique<VertexSE2>(static_cast<int>(k), start)));
  }
  for (std::size_t k = 0; k < odometry.size(); ++k) addEdge(static_cast<int>(k), static_cast<int>(k) + 1, odometry[k]);
  for (const auto& [from, to] : layout.loopClosures) addEdge(from, to, measure(from, to));
  return graph;
}

Graph buildSpatial(const Layout& layout, const PoseGraphOptions& options) {
  NoiseStream noise(mixSeed(options.seed, kNoiseStream));
  Eigen::Matrix<double, 6, 1> diagonal;
  diagonal << Eigen::Vector3d::Constant(1.0 / std::pow(options.translationSigma, 2)),
      Eigen::Vector3d::Constant(4.0 / std::pow(options.rotationSigma, 2));
  const Eigen::Matrix<double, 6, 6> information = diagonal.asDiagonal();
  const auto measure = [&](int from, int to) {
    Eigen::Isometry3d z = layout.poses[from].inverse() * layout.poses[to];
    z.translation() += options.translationSigma * noise.next3();
    z.linear() = z.linear() * expSO3(options.rotationSigma * noise.next3());
    return z;
  };
  Graph graph;
  std::vector<VertexSE3Quat*> vertices;
  const auto addEdge = [&](int from, int to, const Eigen::Isometry3d& z) {
    auto edge = std::make_unique<EdgeSE3Quat>();
    edge->setVertex(0, vertices[from]);
    edge->setVertex(1, vertices[to]);
    edge->setRelativePose(z);
    edge->setInformation(information);
    graph.addEdge(std::move(edge));
  };
  Eigen::Isometry3d start = layout.poses.front();
  vertices.push_back(graph.addVertex(std::make_unique<VertexSE3Quat>(0, start)));
  std::vector<Eigen::Isometry3d> odometry;
  for (std::size_t k = 1; k < layout.poses.size(); ++k) {
    odometry.push_back(measure(static_cast<int>(k) - 1, static_cast<int>(k)));
    start = start * odometry.back();
    vertices.push_back(graph.addVertex(std::make_unique<VertexSE3Quat>(static_cast<int>(k), start)));
  }
  for (std::size_t k = 0; k < odometry.size(); ++k) addEdge(static_cast<int>(k), static_cast<int>(k) + 1, odometry[k]);
  for (const auto& [from, to] : layout.loopClosures) addEdge(from, to, measure(from, to));
  return graph;
}

}  // namespace

PoseGraphShape poseGraphShapeFromName(const std::string& name) {
  if (name == "sphere") return PoseGraphShape::kSphere;
  if (name == "grid") return PoseGraphShape::kGrid;
  throw Error("unknown pose graph shape '" + name + "' (known: sphere, grid)");
}

Graph generatePoseGraph(const PoseGraphOptions& options) {
  if (options.poses < 2) throw Error("pose graph generator: at least 2 poses are needed");
  if (options.dimension != 2 && options.dimension != 3)
    throw Error("pose graph generator: the dimension is 2 or 3, not " + std::to_string(options.dimension));
  if (options.shape == PoseGraphShape::kSphere && options.dimension != 3)
    throw Error("pose graph generator: a sphere is 3D");
  if (!(options.translationSigma > 0.0) || !(options.rotationSigma > 0.0) || !(options.radius > 0.0))
    throw Error("pose graph generator: sigmas and radius must be positive");
  const Layout layout = options.shape == PoseGraphShape::kSphere ? sphereLayout(options) : gridLayout(options);
  return options.dimension == 2 ? buildPlanar(layout, options) : buildSpatial(layout, options);
}

}  // namespace lrsvo
