#include "lrsvo/frontend/odometry/pose_estimator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <random>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {
namespace {

std::vector<double> squaredErrors(const std::vector<PoseMatch>& matches, const Eigen::Isometry3d& pose,
                                  const PinholeIntrinsics& intrinsics) {
  std::vector<double> errors(matches.size());
  for (std::size_t i = 0; i < matches.size(); ++i) {
    const Eigen::Vector3d inCamera = pose * matches[i].point;
    errors[i] = inCamera.z() > 0.0 ? (intrinsics.project(inCamera) - matches[i].pixel).squaredNorm()
                                   : std::numeric_limits<double>::infinity();
  }
  return errors;
}

// The P3P solutions of three matches (none when the points are collinear).
std::vector<Eigen::Isometry3d> solveP3P(const std::vector<PoseMatch>& matches, const std::array<int, 3>& sample,
                                        const PinholeIntrinsics& intrinsics) {
  const Eigen::Vector3d& a = matches[sample[0]].point;
  const Eigen::Vector3d ab = matches[sample[1]].point - a, ac = matches[sample[2]].point - a;
  if (ab.cross(ac).norm() <= 1e-9 * ab.norm() * ac.norm()) return {};
  std::vector<cv::Point3d> objectPoints;
  std::vector<cv::Point2d> imagePoints;
  for (int i : sample) {
    const PoseMatch& m = matches[i];
    objectPoints.emplace_back(m.point.x(), m.point.y(), m.point.z());
    imagePoints.emplace_back(m.pixel.x(), m.pixel.y());
  }
  const cv::Matx33d k(intrinsics.fx, 0.0, intrinsics.cx, 0.0, intrinsics.fy, intrinsics.cy, 0.0, 0.0, 1.0);
  std::vector<cv::Mat> rvecs, tvecs;
  const int count = cv::solveP3P(objectPoints, imagePoints, k, cv::noArray(), rvecs, tvecs, cv::SOLVEPNP_P3P);
  std::vector<Eigen::Isometry3d> poses;
  for (int s = 0; s < count; ++s) {
    const Eigen::Vector3d rvec(rvecs[s].at<double>(0), rvecs[s].at<double>(1), rvecs[s].at<double>(2));
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = expSO3(rvec);
    pose.translation() = Eigen::Vector3d(tvecs[s].at<double>(0), tvecs[s].at<double>(1), tvecs[s].at<double>(2));
    if (pose.matrix().allFinite()) poses.push_back(pose);
  }
  return poses;
}

// Least squares over the inliers: the pose alone, every point fixed.
Eigen::Isometry3d refinePose(const std::vector<PoseMatch>& matches, const std::vector<bool>& inliers,
                             const Eigen::Isometry3d& start, const PinholeIntrinsics& intrinsics,
                             const std::string& solver) {
  Graph graph;
  VertexPose* pose = graph.addVertex(std::make_unique<VertexPose>(0, start));
  int id = 1;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    if (!inliers[i]) continue;
    auto point = std::make_unique<VertexPoint3>(id++, matches[i].point);
    point->setFixed(true);
    auto edge = std::make_unique<EdgeProjectBase>(intrinsics);
    edge->setVertex(0, pose);
    edge->setVertex(1, graph.addVertex(std::move(point)));
    edge->setMeasurement(matches[i].pixel);
    graph.addEdge(std::move(edge));
  }
  SolverOptions options = SolverOptions::fromName(solver);
  options.maxIterations = 20;
  Optimizer(options).optimize(graph);
  return pose->cameraFromWorld();
}

// Hypotheses needed for one all-inlier minimal sample with the given confidence.
int requiredIterations(double inlierFraction, double confidence, int maxIterations) {
  const double allInliers = std::pow(std::clamp(inlierFraction, 0.0, 1.0), 3);
  if (allInliers >= 1.0) return 1;
  // log1p keeps a tiny fraction from rounding the denominator to zero.
  const double denominator = std::log1p(-allInliers);
  if (!(denominator < 0.0)) return maxIterations;
  return static_cast<int>(std::min<double>(std::ceil(std::log(1.0 - confidence) / denominator), maxIterations));
}

}  // namespace

double mlesacScore(const std::vector<double>& squaredErrors_px2, double sigma_px, double imageArea_px2,
                   int emIterations, double* gamma, std::vector<double>* inlierProbabilities) {
  const double variance = sigma_px * sigma_px;
  const double outlierDensity = 1.0 / imageArea_px2;
  std::vector<double> inlierDensity(squaredErrors_px2.size());
  for (std::size_t i = 0; i < inlierDensity.size(); ++i)
    inlierDensity[i] = std::isfinite(squaredErrors_px2[i])
                           ? std::exp(-0.5 * squaredErrors_px2[i] / variance) / (2.0 * std::numbers::pi * variance)
                           : 0.0;
  double g = 0.5;
  for (int iteration = 0; iteration < emIterations; ++iteration) {
    double sum = 0.0;
    for (double p : inlierDensity) sum += g * p / (g * p + (1.0 - g) * outlierDensity);
    g = sum / static_cast<double>(inlierDensity.size());
  }
  double negativeLogLikelihood = 0.0;
  if (inlierProbabilities) inlierProbabilities->resize(inlierDensity.size());
  for (std::size_t i = 0; i < inlierDensity.size(); ++i) {
    const double mixture = g * inlierDensity[i] + (1.0 - g) * outlierDensity;
    negativeLogLikelihood -= std::log(mixture);
    if (inlierProbabilities) (*inlierProbabilities)[i] = g * inlierDensity[i] / mixture;
  }
  if (gamma) *gamma = g;
  return negativeLogLikelihood;
}

PoseEstimate estimatePose(const std::vector<PoseMatch>& matches, const Camera& camera,
                          const PoseEstimatorOptions& options) {
  PoseEstimate result;
  const int count = static_cast<int>(matches.size());
  const int needed = std::max(4, options.minInliers);
  if (count < needed) {
    result.failure = "pose: " + std::to_string(count) + " 2D-3D matches, need at least " + std::to_string(needed);
    return result;
  }
  const PinholeIntrinsics& intrinsics = camera.intrinsics;
  const double area = static_cast<double>(camera.width) * camera.height;
  std::mt19937_64 rng(options.seed);
  std::uniform_int_distribution<int> draw(0, count - 1);

  double bestScore = std::numeric_limits<double>::infinity();
  double bestGamma = 0.0;
  Eigen::Isometry3d best = Eigen::Isometry3d::Identity();
  int required = options.maxIterations;
  while (result.hypotheses < required) {
    ++result.hypotheses;
    std::array<int, 3> sample{draw(rng), 0, 0};
    do sample[1] = draw(rng);
    while (sample[1] == sample[0]);
    do sample[2] = draw(rng);
    while (sample[2] == sample[0] || sample[2] == sample[1]);
    for (const Eigen::Isometry3d& pose : solveP3P(matches, sample, intrinsics)) {
      double gamma = 0.0;
      const double score = mlesacScore(squaredErrors(matches, pose, intrinsics), options.sigma_px, area,
                                       options.emIterations, &gamma, nullptr);
      if (score >= bestScore) continue;
      bestScore = score;
      bestGamma = gamma;
      best = pose;
      required = requiredIterations(bestGamma, options.confidence, options.maxIterations);
    }
  }
  if (!std::isfinite(bestScore)) {
    result.failure = "pose: no P3P hypothesis in " + std::to_string(result.hypotheses) + " samples";
    return result;
  }

  auto classify = [&](const Eigen::Isometry3d& pose) {
    std::vector<double> probabilities;
    result.cameraFromWorld = pose;
    result.score = mlesacScore(squaredErrors(matches, pose, intrinsics), options.sigma_px, area, options.emIterations,
                               &result.inlierFraction, &probabilities);
    result.inliers.assign(matches.size(), false);
    result.inlierCount = 0;
    for (std::size_t i = 0; i < matches.size(); ++i) {
      result.inliers[i] = probabilities[i] > 0.5;
      result.inlierCount += result.inliers[i] ? 1 : 0;
    }
  };
  classify(best);
  if (options.refine && result.inlierCount >= needed)
    classify(refinePose(matches, result.inliers, best, intrinsics, options.refineSolver));
  if (result.inlierCount < options.minInliers) {
    result.failure = "pose: " + std::to_string(result.inlierCount) + " inliers of " + std::to_string(count) +
                     " matches, need " + std::to_string(options.minInliers);
    return result;
  }
  result.success = true;
  return result;
}

}  // namespace lrsvo
