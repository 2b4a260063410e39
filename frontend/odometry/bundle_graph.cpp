#include "lrsvo/frontend/odometry/bundle_graph.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "lrsvo/edges/edge_centre_distance.h"
#include "lrsvo/edges/edge_extrinsic_rate_prior.h"
#include "lrsvo/edges/edge_scale_prior.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/robust_kernel.h"

namespace lrsvo {
namespace {

// The prior's sigma as a fraction of the distance. The data cost does not
// change along the gauge (scaling the map about the held first pose), so at
// the optimum the prior holds the distance exactly whatever its weight. The
// weight matters for conditioning only: a stiff prior adds its curvature to
// diag(H) of every translation coordinate of the pose, and LM's
// multiplicative damping then freezes them. 1 % weighs like a few hundred
// observations of a point at ~15 units.
constexpr double kDistancePriorSigma = 1e-2;

template <class ProjectionEdge>
Eigen::Vector2d residualOf(const Edge* edge) {
  Eigen::Vector2d residual;
  static_cast<const ProjectionEdge*>(edge)->computeResidual(residual);
  return residual;
}

}  // namespace

void holdCentreDistance(Graph& graph, VertexPose* a, VertexPose* b) {
  const double distance = (b->centre() - a->centre()).norm();
  if (!(distance > 0.0))
    throw Error("bundle graph: poses " + std::to_string(a->id()) + " and " + std::to_string(b->id()) +
                " share a centre; their distance cannot fix the unit");
  auto edge = std::make_unique<EdgeCentreDistance>();
  edge->setVertex(0, a);
  edge->setVertex(1, b);
  edge->setMeasurement(Eigen::Matrix<double, 1, 1>(distance));
  const double sigma = kDistancePriorSigma * distance;
  edge->setInformation(Eigen::Matrix<double, 1, 1>(1.0 / (sigma * sigma)));
  graph.addEdge(std::move(edge));
}

BundleGraph::BundleGraph(const Rig& rig, const SparseMap& map, int fixedPoses, BundleGraphOptions options)
    : rig_(rig), options_(std::move(options)) {
  rig.validate();
  extrinsics_.assign(rig.secondaryCount(), nullptr);
  rates_.assign(rig.secondaryCount(), nullptr);
  if (!(options_.sigma_px > 0.0)) throw Error("bundle graph: sigma_px must be positive");
  if (!options_.robustKernel.empty()) kernel_ = makeRobustKernel(options_.robustKernel, options_.robustKernelDelta);
  for (std::size_t i = 0; i < map.cameraFromWorld.size(); ++i) {
    auto pose = std::make_unique<VertexPose>(nextId_++, map.cameraFromWorld[i]);
    pose->setFixed(static_cast<int>(i) < fixedPoses);
    poses_.push_back(graph_.addVertex(std::move(pose)));
  }
  for (const auto& [track, point] : map.points)
    points_[track] = graph_.addVertex(std::make_unique<VertexPoint3>(nextId_++, point));
}

VertexStereoExtrinsic* BundleGraph::addExtrinsic(int camera, const Vector6& value, bool fixed) {
  if (camera < 1 || camera > rig_.secondaryCount())
    throw Error("bundle graph: camera " + std::to_string(camera) + " is not a secondary camera of the rig");
  auto vertex = std::make_unique<VertexStereoExtrinsic>(nextId_++, value);
  vertex->setFixed(fixed);
  extrinsics_[camera - 1] = graph_.addVertex(std::move(vertex));
  return extrinsics_[camera - 1];
}

VertexExtrinsicRate* BundleGraph::addExtrinsicRate(int camera, const Vector6& rate, const Vector6& sigma,
                                                   double referenceTime_s) {
  if (!extrinsic(camera))
    throw Error("bundle graph: camera " + std::to_string(camera) + "'s extrinsic must be added before its rate");
  if (scale_) throw Error("bundle graph: an extrinsic rate cannot join a graph with kappa");
  if (!((sigma.array() > 0.0).all() && sigma.allFinite()))
    throw Error("bundle graph: every sigma of an extrinsic rate's prior must be finite and positive");
  for (const VertexExtrinsicRate* other : rates_)
    if (other && rateReferenceTime_s_ != referenceTime_s)
      throw Error("bundle graph: every extrinsic rate must share one reference time");
  rateReferenceTime_s_ = referenceTime_s;
  rates_[camera - 1] = graph_.addVertex(std::make_unique<VertexExtrinsicRate>(nextId_++, rate));
  auto prior = std::make_unique<EdgeExtrinsicRatePrior>();
  prior->setVertex(0, rates_[camera - 1]);
  prior->setInformation(sigma.array().square().inverse().matrix().asDiagonal());
  graph_.addEdge(std::move(prior));
  return rates_[camera - 1];
}

VertexScale* BundleGraph::addScale(double kappa) {
  if (std::any_of(rates_.begin(), rates_.end(), [](const VertexExtrinsicRate* rate) { return rate != nullptr; }))
    throw Error("bundle graph: kappa cannot join a graph with an extrinsic rate");
  scale_ = graph_.addVertex(std::make_unique<VertexScale>(nextId_++, kappa));
  return scale_;
}

void BundleGraph::holdDistance(int poseA, int poseB) { holdCentreDistance(graph_, poses_.at(poseA), poses_.at(poseB)); }

int BundleGraph::addObservations(int frame, const FrameObservations& observations) {
  VertexPose* pose = poses_.at(frame);
  auto finish = [&]<class ProjectionEdge>(std::unique_ptr<ProjectionEdge> edge, const Observation& observation) {
    measure(*edge, observation.pixel);
    projections_.push_back({frame, observation, graph_.addEdge(std::move(edge)), &residualOf<ProjectionEdge>});
  };
  int added = 0;
  for (const Observation& observation : observations.observations) {
    auto point = points_.find(observation.track);
    if (point == points_.end()) continue;
    if (observation.camera == 0) {
      auto edge = std::make_unique<EdgeProjectBase>(rig_.cameras[0].intrinsics);
      edge->setVertex(0, pose);
      edge->setVertex(1, point->second);
      finish(std::move(edge), observation);
      ++added;
      continue;
    }
    VertexStereoExtrinsic* extrinsic = this->extrinsic(observation.camera);
    if (!extrinsic) continue;
    const SecondaryCamera camera{observation.camera, rig_.cameras[observation.camera].intrinsics};
    if (VertexExtrinsicRate* rate = extrinsicRate(observation.camera)) {
      auto edge = std::make_unique<EdgeProjectSecondaryDrifting>(camera, observations.time_s - rateReferenceTime_s_);
      edge->setVertex(0, pose);
      edge->setVertex(1, point->second);
      edge->setVertex(2, extrinsic);
      edge->setVertex(3, rate);
      finish(std::move(edge), observation);
    } else if (scale_) {
      auto edge = std::make_unique<EdgeProjectSecondaryScaled>(camera);
      edge->setVertex(0, pose);
      edge->setVertex(1, point->second);
      edge->setVertex(2, extrinsic);
      edge->setVertex(3, scale_);
      finish(std::move(edge), observation);
    } else {
      auto edge = std::make_unique<EdgeProjectSecondary>(camera);
      edge->setVertex(0, pose);
      edge->setVertex(1, point->second);
      edge->setVertex(2, extrinsic);
      finish(std::move(edge), observation);
    }
    ++added;
  }
  return added;
}

void BundleGraph::addHeldViewScale(double sigma) {
  if (heldScale_) throw Error("bundle graph: the held views' scale was already added");
  if (!(sigma >= 0.0)) throw Error("bundle graph: the held views' scale sigma must not be negative");
  heldScale_ = graph_.addVertex(std::make_unique<VertexScale>(nextId_++, 1.0));
  if (sigma == 0.0) {
    heldScale_->setFixed(true);
    return;
  }
  auto prior = std::make_unique<EdgeScalePrior>();
  prior->setVertex(0, heldScale_);
  prior->setMeasurement(Eigen::Matrix<double, 1, 1>(1.0));
  prior->setInformation(Eigen::Matrix<double, 1, 1>(1.0 / (sigma * sigma)));
  graph_.addEdge(std::move(prior));
}

int BundleGraph::addHeldView(const Eigen::Isometry3d& cameraFromWorld, const Eigen::Vector3d& origin,
                             const FrameObservations& observations) {
  if (!heldScale_) throw Error("bundle graph: addHeldViewScale must come before addHeldView");
  int added = 0;
  for (const Observation& observation : observations.observations) {
    auto point = points_.find(observation.track);
    if (observation.camera != 0 || point == points_.end()) continue;
    auto edge = std::make_unique<EdgeProjectHeldView>(rig_.cameras[0].intrinsics, cameraFromWorld, origin);
    edge->setVertex(0, point->second);
    edge->setVertex(1, heldScale_);
    measure(*edge, observation.pixel);
    graph_.addEdge(std::move(edge));
    ++added;
  }
  return added;
}

std::vector<HeldCoordinate> BundleGraph::scaleGaugeCoordinates(const Bounds* enforced) const {
  constexpr double kActiveFraction = 0.02;  // of the half-width: an angle this close to a bound is held by it
  std::vector<HeldCoordinate> held;
  for (const VertexStereoExtrinsic* extrinsic : extrinsics_)
    if (extrinsic && !extrinsic->fixed())
      for (int i = 0; i < 3; ++i) held.push_back({extrinsic, i});
  for (const VertexExtrinsicRate* rate : rates_)
    if (rate && !rate->fixed())
      for (int i = 0; i < 3; ++i) held.push_back({rate, i});
  if (!enforced) return held;
  for (const Bounds::Bound& bound : enforced->all()) {
    const double value = Bounds::value(bound);
    const bool atBound = std::min(value - bound.lower, bound.upper - value) <= kActiveFraction * bound.halfWidth();
    if (bound.index >= 3 && atBound) held.push_back({bound.vertex, bound.index});
  }
  return held;
}

Bounds BundleGraph::extrinsicBounds() const {
  Bounds bounds;
  for (int k = 1; k <= rig_.secondaryCount(); ++k)
    if (extrinsics_[k - 1] && !extrinsics_[k - 1]->fixed()) rig_.addBounds(bounds, extrinsics_[k - 1], k);
  return bounds;
}

VertexStereoExtrinsic* BundleGraph::extrinsic(int camera) const {
  if (camera < 1 || camera > rig_.secondaryCount()) return nullptr;
  return extrinsics_[camera - 1];
}

VertexExtrinsicRate* BundleGraph::extrinsicRate(int camera) const {
  if (camera < 1 || camera > rig_.secondaryCount()) return nullptr;
  return rates_[camera - 1];
}

SparseMap BundleGraph::map() const {
  SparseMap map;
  for (const VertexPose* pose : poses_) map.cameraFromWorld.push_back(pose->cameraFromWorld());
  for (const auto& [track, point] : points_) map.points[track] = point->estimate();
  return map;
}

std::vector<BundleGraph::Vector6> BundleGraph::extrinsics() const {
  std::vector<Vector6> values;
  for (int k = 1; k <= rig_.secondaryCount(); ++k)
    values.push_back(extrinsics_[k - 1] ? extrinsics_[k - 1]->estimate() : rig_.extrinsics[k - 1]);
  return values;
}

double BundleGraph::rmsReprojectionError_px() const {
  double sum = 0.0;
  for (const Projection& projection : projections_) sum += projection.residual(projection.edge).squaredNorm();
  return projections_.empty() ? 0.0 : std::sqrt(sum / (2.0 * static_cast<double>(projections_.size())));
}

std::vector<ProjectionError> BundleGraph::projectionErrors() const {
  std::vector<ProjectionError> errors;
  errors.reserve(projections_.size());
  for (const Projection& projection : projections_)
    errors.push_back({projection.frame, projection.observation, projection.residual(projection.edge).norm()});
  return errors;
}

}  // namespace lrsvo
