#pragma once

#include <deque>
#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/constraints/bounds.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/odometry_options.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/graph/solver_summary.h"

namespace lrsvo {

class BundleGraph;
struct SparseMap;
struct WindowOutliers;

// A frame of the sliding window: its base pose and everything it observed.
struct Keyframe {
  int frame = 0;
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
  FrameObservations observations;
};

struct WindowAdjustment {
  SolverSummary summary;
  double rmsError_px = 0.0;          // per image coordinate, before outliers are removed
  double outlierThreshold_px = 0.0;  // the base camera's reprojection error above which observations were removed
  std::vector<int> rejectedTracks;   // tracks removed for a base-camera outlier
  int removedObservations = 0;
};

// The paper's sliding window (Section 4.1): the most recent keyframes, the
// points their tracks measure, and one stereo extrinsic S per secondary
// camera shared by every keyframe. Each adjustment builds the window as a
// graph (BundleGraph: poses, points, S) and solves it with the chosen solver
// and constraint method; the oldest keyframe is retired when the window is full.
class SlidingWindow {
 public:
  using Vector6 = VertexStereoExtrinsic::Vector6;

  // The window refers to its owner's rig and options: it is neither copyable nor movable.
  SlidingWindow(const Rig& rig, const OdometryOptions& options);
  SlidingWindow(const SlidingWindow&) = delete;
  SlidingWindow& operator=(const SlidingWindow&) = delete;

  // Starts over from an initialised map (its keyframes oldest first) whose
  // scale has this relative standard deviation.
  void reset(std::vector<Keyframe> keyframes, std::map<int, Eigen::Vector3d> points, std::vector<Vector6> extrinsics,
             double scaleRelativeStd = 0.05);
  void addKeyframe(Keyframe keyframe);
  // Triangulates every unmapped track the base camera saw in at least
  // minTriangulationViews keyframes (with its secondary views as further
  // rays, through the current S). Returns the number of new points.
  int triangulateNewTracks();
  // Bundle adjustment of the window, then removal of outlying observations:
  // builds the window as a graph, solves it, writes the estimates back and
  // removes the observations findWindowOutliers condemns.
  WindowAdjustment adjust();
  // Drops the oldest keyframes beyond windowSize (they become held anchors),
  // and the points no kept keyframe observes.
  void retire();
  // Forgets tracks (a pose estimate rejected them): their points and observations.
  void removeTracks(const std::vector<int>& tracks);

  const std::deque<Keyframe>& keyframes() const { return keyframes_; }
  // The most recently retired keyframes, held in each adjustment (OdometryOptions::anchorKeyframes).
  const std::deque<Keyframe>& anchors() const { return anchors_; }
  const std::map<int, Eigen::Vector3d>& points() const { return points_; }
  // S at the newest keyframe of the last adjustment (per secondary camera).
  const std::vector<Vector6>& extrinsics() const { return extrinsics_; }
  // S at time t: the last adjustment's S moved on at its rate (zero when the
  // window holds one S for all its keyframes: OdometryOptions::extrinsicRateSigma 0),
  // and kept in the rig's box when bounded.
  std::vector<Vector6> extrinsicsAt(double time_s) const;
  // S's rate per second (per secondary camera).
  const std::vector<Vector6>& extrinsicRates() const { return rates_; }
  // The relative standard deviation of the map's scale the window carries.
  double scaleRelativeStd() const;
  // Camera k's pose (camera-from-world) for a base pose at time t, through S then.
  Eigen::Isometry3d cameraFromWorld(const Eigen::Isometry3d& baseFromWorld, int camera, double time_s) const;

 private:
  // Where an adjustment stands: the time S is estimated at, the centre the
  // held views scale about (the oldest keyframe's), the held scale's prior.
  struct WindowFrame {
    double referenceTime_s = 0.0;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    double scalePriorVariance = 0.0;
  };
  // The keyframes' poses and the points at least two of them observe.
  SparseMap windowMap() const;
  // Adds S (and its rate), every keyframe's observations and the held views.
  void addToBundle(BundleGraph& bundle, const WindowFrame& frame) const;
  SolverSummary solve(BundleGraph& bundle, const Bounds& bounds) const;
  // Takes the solved poses, points, S, its rate and the held scale into the window.
  void writeBack(BundleGraph& bundle, const Bounds& bounds, const WindowFrame& frame);
  // Returns the number of observations removed.
  int removeOutliers(const WindowOutliers& outliers);
  bool extrinsicFixed() const { return options_.extrinsicMode == ExtrinsicMode::kRigid; }
  bool drifting() const { return !extrinsicFixed() && options_.extrinsicRateSigma > 0.0; }
  // Camera k's S at time t (extrinsicsAt).
  Vector6 extrinsicAt(int camera, double time_s) const;

  const Rig& rig_;
  const OdometryOptions& options_;
  std::deque<Keyframe> keyframes_;
  std::deque<Keyframe> anchors_;  // oldest first
  std::map<int, Eigen::Vector3d> points_;
  std::vector<Vector6> extrinsics_;  // [k - 1], at extrinsicTime_s_
  std::vector<Vector6> rates_;       // [k - 1], per second
  double extrinsicTime_s_ = 0.0;
  double scaleVariance_ = 0.0;  // relative, of the map's scale
};

}  // namespace lrsvo
