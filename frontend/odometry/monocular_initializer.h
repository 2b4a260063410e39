#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/observations.h"
#include "lrsvo/frontend/odometry/pose_estimator.h"
#include "lrsvo/frontend/odometry/rig.h"
#include "lrsvo/frontend/odometry/sparse_map.h"
#include "lrsvo/frontend/odometry/triangulation.h"
#include "lrsvo/frontend/odometry/two_view.h"
#include "lrsvo/graph/solver_options.h"
#include "lrsvo/graph/solver_summary.h"

namespace lrsvo {

struct MonocularOptions {
  int frames = 10;               // base frames used, from the first
  double initialBaseline = 1.0;  // distance given to frames 0 and 1: the map's unit
  // The two-view pair is frame 0 and the last frame still sharing this
  // fraction of frame 0's tracks: the widest baseline with a well-populated
  // overlap. Frames 0 and 1 alone leave the essential matrix ill-conditioned
  // at long range (measured at 250 m, 6.7 m apart: three of six seeds failed
  // with frames 0-1, none with the widest pair).
  double pairOverlap = 0.5;
  int minViews = 2;        // views a track needs before it is triangulated (after the first pair)
  int minPosePoints = 12;  // mapped points a frame must see for its pose
  int minPairPoints = 30;  // points triangulated from the first pair, at least
  TwoViewOptions twoView;
  PoseEstimatorOptions pose;
  // A point needs rays 2 mrad apart (depth up to ~500 x the widest baseline
  // it was seen over) and an RMS reprojection error of at most 3 px.
  TriangulationOptions triangulation{.maxIterations = 10, .minParallax_rad = 2e-3, .maxReprojectionError_px = 3.0};
  BundleGraphOptions bundle;
  SolverOptions solver{.linearSolver = "schur_dense", .lm = {}, .maxIterations = 50};  // each bundle adjustment
  std::uint64_t seed = 1;
};

struct MonocularResult {
  bool success = false;
  std::string failure;  // why not, when !success
  SparseMap map;  // every frame on success (empty otherwise); world = the first camera, |C_1 - C_0| = initialBaseline
  SolverSummary summary;                 // the last bundle adjustment
  double rmsReprojectionError_px = 0.0;  // per image coordinate, after the last bundle adjustment
};

// Monocular visual odometry over the base camera of the first N frames, at an
// arbitrary scale (docs/method.md, long-range initialisation, steps 2-3):
//  - two-view pose of frame 0 and the pair frame p (see pairOverlap) at unit
//    distance; triangulate their shared inlier tracks;
//  - each other frame (1..p-1, then p+1..N-1): pose by P3P in MLESAC from its
//    base observations of mapped points; triangulate tracks seen in
//    >= minViews posed frames; bundle adjustment over every posed frame;
//  - finally the map is scaled so that frames 0 and 1 are initialBaseline apart.
// Gauge: pose 0 is held, and the distance between frames 0 and p by a prior
// (EdgeCentreDistance) rather than by holding pose p, whose rotation and
// direction of travel the other frames then still refine. Only the base
// camera (camera 0) is used. Reports failure in the result; throws
// lrsvo::Error on an invalid rig or options.
//
// Near-planar ground lets the pair fit two motions (twoViewHypotheses): one
// map is built from each, in the hypotheses' order. Only relief tells them
// apart in the base camera, so a caller with a second camera should judge
// them with it (LongRangeInitializer does).
std::vector<MonocularResult> buildMonocularMaps(const Rig& rig, const std::vector<FrameObservations>& frames,
                                                const MonocularOptions& options = {});
// Of buildMonocularMaps, the successful map with the lowest RMS reprojection
// error; the first hypothesis's failure when none succeeds.
MonocularResult buildMonocularMap(const Rig& rig, const std::vector<FrameObservations>& frames,
                                  const MonocularOptions& options = {});

}  // namespace lrsvo
