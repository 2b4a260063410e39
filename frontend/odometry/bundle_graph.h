#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lrsvo/constraints/bounds.h"
#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_held_view.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/edges/edge_project_secondary_drifting.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/frontend/odometry/sparse_map.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/marginal_covariance.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/vertices/vertex_extrinsic_rate.h"
#include "lrsvo/vertices/vertex_point3.h"
#include "lrsvo/vertices/vertex_pose.h"
#include "lrsvo/vertices/vertex_scale.h"
#include "lrsvo/vertices/vertex_stereo_extrinsic.h"

namespace lrsvo {

// Holds the unit of a map whose scale is free (a monocular map): a prior
// keeps the distance between the centres of a and b at its current value.
void holdCentreDistance(Graph& graph, VertexPose* a, VertexPose* b);

// The reprojection error of one observation in the graph, in pixels.
struct ProjectionError {
  int frame = 0;  // the pose index
  Observation observation;
  double error_px = 0.0;  // |projection - measurement|
};

struct BundleGraphOptions {
  double sigma_px = 1.0;               // measurement noise: information = I / sigma^2
  std::string robustKernel = "Huber";  // "" for none, else a registered kernel
  double robustKernelDelta = 3.0;      // in sigmas (the whitened residual norm)
};

// A bundle-adjustment graph over a sparse map and the rig's observations of
// it, as the initialisers build it: one VertexPose per frame (base camera),
// one VertexPoint3 per mapped track, optionally one VertexStereoExtrinsic per
// secondary camera and one VertexScale (kappa) shared by all of them.
class BundleGraph {
 public:
  using Vector6 = VertexStereoExtrinsic::Vector6;

  // Poses and points from the map; the first `fixedPoses` poses are held.
  BundleGraph(const Rig& rig, const SparseMap& map, int fixedPoses, BundleGraphOptions options = {});

  // Secondary camera k's extrinsic (k >= 1), held at `value` when fixed.
  VertexStereoExtrinsic* addExtrinsic(int camera, const Vector6& value, bool fixed);
  // Lets camera k's extrinsic (added first) change linearly in time: a frame
  // at time t sees s + (t - referenceTime_s) * rate (VertexExtrinsicRate),
  // the rate starting at `rate` with a prior N(0, diag(sigma^2)), every sigma
  // > 0. Applies to the secondary edges added after this call; not with kappa.
  VertexExtrinsicRate* addExtrinsicRate(int camera, const Vector6& rate, const Vector6& sigma, double referenceTime_s);
  // kappa (docs/method.md, eq. 5) on every secondary edge added after this call.
  VertexScale* addScale(double kappa);
  // Holds the map's unit at the distance between poses a and b (holdCentreDistance).
  void holdDistance(int poseA, int poseB);
  // One edge per observation of frame `frame` whose track is mapped: base
  // observations always, secondary ones when that camera's extrinsic was
  // added. Returns the number of edges added.
  int addObservations(int frame, const FrameObservations& observations);
  // The scale s every held view's centre slides with, starting at 1, with a
  // prior s ~ N(1, sigma^2); sigma 0 holds s at 1. Call once, before addHeldView.
  void addHeldViewScale(double sigma);
  // A held view (EdgeProjectHeldView): base observations of mapped tracks from
  // a fixed orientation, the centre sliding with the held views' scale about
  // `origin`. Not counted in the RMS or projection errors. Returns the number
  // of edges added.
  int addHeldView(const Eigen::Isometry3d& cameraFromWorld, const Eigen::Vector3d& origin,
                  const FrameObservations& observations);
  // Secondary camera k's extrinsic rate vertex, or nullptr.
  VertexExtrinsicRate* extrinsicRate(int camera) const;
  // The held views' scale s, or nullptr before addHeldViewScale.
  VertexScale* heldViewScale() const { return heldScale_; }
  // What a marginal covariance of the map's scale must condition on: the free
  // extrinsics' centres c (scaling the map and c together changes no
  // projection, so only c's bounds fix that gauge; likewise c's rate) and, of `enforced` (the
  // bounds the solve kept, or none), the angles within 2 % of their
  // half-width from a bound, which the bound rather than the data holds.
  std::vector<HeldCoordinate> scaleGaugeCoordinates(const Bounds* enforced) const;
  // The rig's box around calibration on every (free) extrinsic vertex.
  Bounds extrinsicBounds() const;

  Graph& graph() { return graph_; }
  VertexScale* scale() const { return scale_; }
  const VertexPose* pose(int index) const { return poses_.at(index); }
  // Secondary camera k's extrinsic vertex, or nullptr.
  VertexStereoExtrinsic* extrinsic(int camera) const;
  // The estimates, in the graph's unit.
  SparseMap map() const;
  std::vector<Vector6> extrinsics() const;
  // RMS reprojection error per image coordinate over every projection edge, in pixels.
  double rmsReprojectionError_px() const;
  // Every projection edge's current error, in the order the observations were added.
  std::vector<ProjectionError> projectionErrors() const;

 private:
  const Rig& rig_;
  BundleGraphOptions options_;
  std::shared_ptr<RobustKernel> kernel_;  // shared by every projection edge; nullptr for none
  Graph graph_;
  int nextId_ = 0;
  std::vector<VertexPose*> poses_;
  std::map<int, VertexPoint3*> points_;
  std::vector<VertexStereoExtrinsic*> extrinsics_;  // [k - 1], nullptr when not added
  std::vector<VertexExtrinsicRate*> rates_;         // [k - 1], nullptr when not added
  double rateReferenceTime_s_ = 0.0;
  VertexScale* scale_ = nullptr;
  VertexScale* heldScale_ = nullptr;  // of the held views (addHeldViewScale)
  // One per projection edge: which observation it measures and how to read
  // its residual (the edge types share no residual interface).
  struct Projection {
    int frame;
    Observation observation;
    const Edge* edge;
    Eigen::Vector2d (*residual)(const Edge*);
  };
  std::vector<Projection> projections_;

  // A projection edge's measured pixel, its noise (options_.sigma_px) and robust kernel.
  template <class ProjectionEdge>
  void measure(ProjectionEdge& edge, const Eigen::Vector2d& pixel) const {
    edge.setMeasurement(pixel);
    edge.setInformation(Eigen::Matrix2d::Identity() / (options_.sigma_px * options_.sigma_px));
    if (kernel_) edge.setRobustKernel(kernel_);
  }
};

}  // namespace lrsvo
