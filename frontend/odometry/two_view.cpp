#include "lrsvo/frontend/odometry/two_view.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <utility>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/frontend/odometry/bundle_graph.h"
#include "lrsvo/frontend/odometry/triangulation.h"
#include "lrsvo/graph/optimizer.h"

namespace lrsvo {
namespace {

// The pixels of one camera's observations, by track (sorted, so the
// correspondences come out in the same order every time).
std::map<int, Eigen::Vector2d> pixelsByTrack(const FrameObservations& frame, int camera) {
  std::map<int, Eigen::Vector2d> pixels;
  for (const Observation& observation : frame.observations)
    if (observation.camera == camera) pixels[observation.track] = observation.pixel;
  return pixels;
}

cv::Point2d normalised(const Eigen::Vector2d& pixel, const PinholeIntrinsics& k) {
  return {(pixel.x() - k.cx) / k.fx, (pixel.y() - k.cy) / k.fy};
}

// Bundle adjustment of the pair: camera a held at the origin, the distance to
// b held at 1 (the pair's unit), the inliers' points triangulated first.
void refine(TwoViewResult& result, const std::map<int, Eigen::Vector2d>& pixelsA,
            const std::map<int, Eigen::Vector2d>& pixelsB, const PinholeIntrinsics& intrinsics,
            const std::string& solver) {
  Graph graph;
  VertexPose* a = graph.addVertex(std::make_unique<VertexPose>(0));
  a->setFixed(true);
  VertexPose* b = graph.addVertex(std::make_unique<VertexPose>(1, result.bFromA()));
  holdCentreDistance(graph, a, b);
  int points = 0;
  for (int track : result.inlierTracks) {
    const Eigen::Vector2d& pixelA = pixelsA.at(track);
    const Eigen::Vector2d& pixelB = pixelsB.at(track);
    const TriangulationResult point =
        triangulate({{a->cameraFromWorld(), intrinsics, pixelA}, {b->cameraFromWorld(), intrinsics, pixelB}});
    if (!point.valid) continue;
    VertexPoint3* vertex = graph.addVertex(std::make_unique<VertexPoint3>(2 + points++, point.point));
    for (auto [pose, pixel] : {std::pair{a, pixelA}, std::pair{b, pixelB}}) {
      auto edge = std::make_unique<EdgeProjectBase>(intrinsics);
      edge->setVertex(0, pose);
      edge->setVertex(1, vertex);
      edge->setMeasurement(pixel);
      graph.addEdge(std::move(edge));
    }
  }
  if (points < 5) return;  // nothing to refine with; keep RANSAC's pose
  Optimizer(SolverOptions::fromName(solver)).optimize(graph);
  result.rotation = b->rotation();
  result.translation = b->translation().normalized();
}

// The tracks two frames share, with their normalised image coordinates.
struct Correspondences {
  std::vector<int> tracks;
  std::vector<cv::Point2d> pointsA, pointsB;
};

Correspondences correspondences(const std::map<int, Eigen::Vector2d>& pixelsA,
                                const std::map<int, Eigen::Vector2d>& pixelsB, const PinholeIntrinsics& intrinsics) {
  Correspondences shared;
  for (const auto& [track, pixel] : pixelsA) {
    auto it = pixelsB.find(track);
    if (it == pixelsB.end()) continue;
    shared.tracks.push_back(track);
    shared.pointsA.push_back(normalised(pixel, intrinsics));
    shared.pointsB.push_back(normalised(it->second, intrinsics));
  }
  return shared;
}

double directionAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool isNewMotion(const std::vector<TwoViewResult>& known, const Eigen::Matrix3d& rotation,
                 const Eigen::Vector3d& translation) {
  // The planar twin moves along the ground's normal instead of along the
  // ground: tens of degrees apart, against well under a degree for two
  // estimates of one motion.
  constexpr double kSameMotion_rad = 0.1;
  for (const TwoViewResult& motion : known)
    if (directionAngle(motion.translation, translation) < kSameMotion_rad &&
        Eigen::AngleAxisd(motion.rotation.transpose() * rotation).angle() < kSameMotion_rad)
      return false;
  return true;
}

// Sets a motion as OpenCV's recoverPose gives it (rotation, translation, the
// mask of its inliers among the correspondences), with the inliers' tracks.
void setMotion(TwoViewResult& motion, const cv::Mat& rotation, const cv::Mat& translation, const cv::Mat& inlierMask,
               const std::vector<int>& tracks) {
  for (int r = 0; r < 3; ++r) {
    motion.translation[r] = translation.at<double>(r);
    for (int c = 0; c < 3; ++c) motion.rotation(r, c) = rotation.at<double>(r, c);
  }
  motion.translation.normalize();
  for (std::size_t i = 0; i < tracks.size(); ++i)
    if (inlierMask.at<unsigned char>(static_cast<int>(i))) motion.inlierTracks.push_back(tracks[i]);
}

TwoViewResult failed(TwoViewResult result, const std::string& why) {
  result.success = false;
  result.failure = "two-view: " + why;
  return result;
}

// The two frames' pixels by track and their correspondences, gathered once
// for both the essential matrix and the homography.
struct SharedTracks {
  SharedTracks(const FrameObservations& a, const FrameObservations& b, const PinholeIntrinsics& intrinsics, int camera)
      : pixelsA(pixelsByTrack(a, camera)),
        pixelsB(pixelsByTrack(b, camera)),
        shared(correspondences(pixelsA, pixelsB, intrinsics)) {}
  std::map<int, Eigen::Vector2d> pixelsA, pixelsB;
  Correspondences shared;
};

TwoViewResult essentialMotion(const SharedTracks& frames, const PinholeIntrinsics& intrinsics,
                              const TwoViewOptions& options) {
  TwoViewResult result;
  const auto& [tracks, pointsA, pointsB] = frames.shared;
  result.correspondences = static_cast<int>(tracks.size());
  if (result.correspondences < std::max(5, options.minInliers))
    return failed(result, std::to_string(result.correspondences) + " shared tracks, need at least " +
                              std::to_string(std::max(5, options.minInliers)));

  // OpenCV's RANSAC draws its samples from a fixed internal stream
  // (cv::setRNGSeed does not reach it), so the seed acts through the order of
  // the correspondences: each attempt shuffles them. Near-planar ground seen
  // from far away lets RANSAC settle on the twin of the true essential
  // matrix (motion along the ground's normal) with nearly as many inliers
  // under the Sampson distance; the attempt with the most inliers in front of
  // both cameras wins, which may still be the twin (see twoViewHypotheses).
  const cv::Matx33d identity = cv::Matx33d::eye();
  std::mt19937_64 rng(options.seed);
  std::vector<int> order(tracks.size());
  std::iota(order.begin(), order.end(), 0);
  int bestInFront = -1;
  cv::Mat rotation, translation, inlierMask;
  for (int attempt = 0; attempt < options.attempts; ++attempt) {
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<cv::Point2d> shuffledA, shuffledB;
    for (int i : order) {
      shuffledA.push_back(pointsA[i]);
      shuffledB.push_back(pointsB[i]);
    }
    cv::Mat mask;
    const cv::Mat essential = cv::findEssentialMat(shuffledA, shuffledB, identity, cv::RANSAC, options.confidence,
                                                   options.ransacThreshold_px / intrinsics.fx, mask);
    // findEssentialMat may return several stacked 3x3 solutions; the first is RANSAC's best.
    if (essential.rows < 3 || essential.cols != 3) continue;
    cv::Mat r, t;
    const int inFront = cv::recoverPose(essential.rowRange(0, 3), shuffledA, shuffledB, identity, r, t, mask);
    if (inFront <= bestInFront) continue;
    bestInFront = inFront;
    rotation = r;
    translation = t;
    inlierMask = cv::Mat::zeros(static_cast<int>(tracks.size()), 1, CV_8U);
    for (std::size_t i = 0; i < order.size(); ++i)
      inlierMask.at<unsigned char>(order[i]) = mask.at<unsigned char>(static_cast<int>(i));
  }
  if (bestInFront < 0) return failed(result, "no essential matrix found");
  if (bestInFront < options.minInliers)
    return failed(result, std::to_string(bestInFront) + " of " + std::to_string(result.correspondences) +
                              " correspondences are inliers in front of both cameras, need " +
                              std::to_string(options.minInliers) + " (too little parallax or motion?)");

  setMotion(result, rotation, translation, inlierMask, tracks);
  if (options.refine) refine(result, frames.pixelsA, frames.pixelsB, intrinsics, options.refineSolver);
  result.success = true;
  return result;
}

}  // namespace

Eigen::Isometry3d TwoViewResult::bFromA(double distance) const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = distance * translation;
  return pose;
}

TwoViewResult estimateTwoView(const FrameObservations& a, const FrameObservations& b,
                              const PinholeIntrinsics& intrinsics, const TwoViewOptions& options) {
  return essentialMotion(SharedTracks(a, b, intrinsics, options.camera), intrinsics, options);
}

std::vector<TwoViewResult> twoViewHypotheses(const FrameObservations& a, const FrameObservations& b,
                                             const PinholeIntrinsics& intrinsics, const TwoViewOptions& options) {
  const SharedTracks frames(a, b, intrinsics, options.camera);
  std::vector<TwoViewResult> hypotheses = {essentialMotion(frames, intrinsics, options)};
  if (!hypotheses.front().success) return hypotheses;
  const Correspondences& shared = frames.shared;

  // The ground's homography, then each of its motions whose essential matrix [t]x R, decomposed by the
  // cheirality test like the first hypothesis's, keeps nearly all of the homography's inliers in front of both
  // cameras: a motion that puts a fifth of the ground behind a camera is not the ground's.
  constexpr double kMinInFrontFraction = 0.8;
  cv::Mat planeMask;
  const cv::Mat homography =
      cv::findHomography(shared.pointsA, shared.pointsB, cv::RANSAC, options.ransacThreshold_px / intrinsics.fx,
                         planeMask, 2000, options.confidence);
  if (homography.empty()) return hypotheses;
  const int planeInliers = cv::countNonZero(planeMask);
  if (planeInliers < options.minInliers) return hypotheses;
  std::vector<cv::Mat> rotations, translations, normals;
  cv::decomposeHomographyMat(homography, cv::Matx33d::eye(), rotations, translations, normals);
  for (std::size_t solution = 0; solution < rotations.size(); ++solution) {
    const cv::Mat& t = translations[solution];
    const cv::Mat skew = (cv::Mat_<double>(3, 3) << 0, -t.at<double>(2), t.at<double>(1), t.at<double>(2), 0,
                          -t.at<double>(0), -t.at<double>(1), t.at<double>(0), 0);
    cv::Mat rotation, translation, inFrontMask = planeMask.clone();
    const int inFront = cv::recoverPose(skew * rotations[solution], shared.pointsA, shared.pointsB, cv::Matx33d::eye(),
                                        rotation, translation, inFrontMask);
    if (inFront < kMinInFrontFraction * planeInliers) continue;
    TwoViewResult motion;
    setMotion(motion, rotation, translation, inFrontMask, shared.tracks);
    if (!isNewMotion(hypotheses, motion.rotation, motion.translation)) continue;
    motion.correspondences = hypotheses.front().correspondences;
    if (options.refine) refine(motion, frames.pixelsA, frames.pixelsB, intrinsics, options.refineSolver);
    if (!isNewMotion(hypotheses, motion.rotation, motion.translation)) continue;
    motion.success = true;
    hypotheses.push_back(std::move(motion));
  }
  return hypotheses;
}

}  // namespace lrsvo
