#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lrsvo/frontend/odometry/rig.h"

namespace lrsvo {

// A known world point and where one camera measured it.
struct PoseMatch {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

struct PoseEstimatorOptions {
  double sigma_px = 1.0;      // inlier noise: the Gaussian of the MLESAC mixture
  double confidence = 0.999;  // stop once a sample free of outliers was drawn with this probability
  int maxIterations = 1000;   // hypotheses at most
  int emIterations = 5;       // EM steps estimating the inlier fraction gamma, per hypothesis
  int minInliers = 6;         // fewer is a failure
  bool refine = true;         // least-squares refinement of the best hypothesis on its inliers
  std::string refineSolver = "lm_dense";
  std::uint64_t seed = 1;
};

struct PoseEstimate {
  bool success = false;
  std::string failure;  // why not, when !success
  Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
  std::vector<bool> inliers;  // per match: posterior inlier probability > 1/2
  int inlierCount = 0;
  double inlierFraction = 0.0;  // gamma, the mixing weight
  double score = 0.0;           // negative log-likelihood of all matches under the mixture
  int hypotheses = 0;           // P3P samples drawn
};

// The MLESAC score (Torr & Zisserman 2000) of squared reprojection errors:
// each error comes from gamma N(0, sigma^2 I) + (1 - gamma) U(image), with
// gamma fitted by EM. Returns the negative log-likelihood and writes gamma
// and the posterior inlier probabilities. Non-finite errors (a point behind
// the camera) count as outliers.
double mlesacScore(const std::vector<double>& squaredErrors_px2, double sigma_px, double imageArea_px2,
                   int emIterations, double* gamma, std::vector<double>* inlierProbabilities);

// Camera-from-world pose of one camera from 2D-3D matches: minimal P3P
// samples (cv::solveP3P, up to four solutions each) scored by MLESAC, seeded
// sampling, iterations adapted to the estimated inlier fraction; then a
// least-squares refinement over the inliers (one VertexPose, EdgeProjectBase
// to fixed points). Reports failure (does not throw) on too few matches or inliers.
PoseEstimate estimatePose(const std::vector<PoseMatch>& matches, const Camera& camera,
                          const PoseEstimatorOptions& options = {});

}  // namespace lrsvo
