#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/edges/pinhole.h"
#include "lrsvo/frontend/odometry/observations.h"

namespace lrsvo {

struct TwoViewOptions {
  // Sampson distance of an inlier, in pixels: with sigma px of noise in each
  // image the distance of a true match has a spread of about sqrt(2) sigma.
  double ransacThreshold_px = 3.0;
  double confidence = 0.999;  // RANSAC's probability of drawing one outlier-free sample
  int minInliers = 15;        // fewer inliers (after the cheirality test) is a failure
  int camera = 0;             // which camera of the rig the two frames' observations come from
  bool refine = true;         // bundle adjustment of the pair over the inliers after RANSAC
  std::string refineSolver = "lm_schur_dense";
  int attempts = 5;  // RANSAC runs, each on a seeded shuffle of the correspondences
  std::uint64_t seed = 1;
};

// The relative pose of two frames of one camera: X_b = R X_a + t with |t| = 1
// (the scale of a monocular pair is unknown).
struct TwoViewResult {
  bool success = false;
  std::string failure;  // why not, when !success
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  std::vector<int> inlierTracks;  // tracks consistent with the essential matrix and in front of both cameras
  int correspondences = 0;        // tracks the two frames share
  // camera b from camera a as an isometry, translation scaled to `distance`.
  Eigen::Isometry3d bFromA(double distance = 1.0) const;
};

// Five-point essential matrix in RANSAC on normalised image coordinates
// (cv::findEssentialMat), decomposed by cv::recoverPose (the cheirality test
// picks one of the four solutions); of `attempts` runs the one with the most
// inliers in front of both cameras is kept. RANSAC keeps the best minimal sample's
// model, so with `refine` the pose is then adjusted with the inliers'
// triangulated points (camera a held, the distance held at 1). Reports
// failure (does not throw) when there are too few correspondences or inliers.
TwoViewResult estimateTwoView(const FrameObservations& a, const FrameObservations& b,
                              const PinholeIntrinsics& intrinsics, const TwoViewOptions& options = {});

// The motions two frames of near-planar ground may have come from. Seen from
// far away, ground that is nearly a plane fits two motions almost equally
// well under the epipolar constraint: the true one, and its planar twin,
// which moves along the ground's normal, turning as it goes. Five-point
// RANSAC with the cheirality test may settle on the twin; the ground's
// homography still decomposes into the true motion. So a caller with more
// evidence (more frames, a second camera) should try each hypothesis. The
// first is estimateTwoView's (and its failure, if it fails); then every other
// motion of the correspondences' homography (cv::decomposeHomographyMat)
// that keeps at least 80 % of the homography's inliers in front of both
// cameras, refined like the first over those inliers.
std::vector<TwoViewResult> twoViewHypotheses(const FrameObservations& a, const FrameObservations& b,
                                             const PinholeIntrinsics& intrinsics, const TwoViewOptions& options = {});

}  // namespace lrsvo
