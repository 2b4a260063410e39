#include "lrsvo/sim/window_problem.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>

#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo {
namespace {

using Vector6 = VertexStereoExtrinsic::Vector6;

void check(bool condition, const std::string& message) {
  if (!condition) throw Error("window problem: " + message);
}

void validate(const WindowProblemOptions& o) {
  check(o.frames >= 2, "need at least 2 frames");
  check(o.points >= 1, "need at least 1 point");
  check(o.altitude_m > o.terrainRelief_m && o.terrainRelief_m >= 0.0, "need altitude_m > terrainRelief_m >= 0");
  check(o.frameSpacing_m > 0.0 && o.baseline_m > 0.0, "need a positive frame spacing and baseline");
  check(o.imageWidth > 2 * o.imageMargin_px && o.imageHeight > 2 * o.imageMargin_px && o.imageMargin_px >= 0.0,
        "image too small for its margin");
  check(o.horizontalFov_deg > 0.0 && o.horizontalFov_deg < 180.0, "horizontal field of view must be in (0, 180) deg");
  check(o.pixelNoise >= 0.0 && o.measurementSigma > 0.0, "need pixelNoise >= 0 and measurementSigma > 0");
  check(o.minTrackLength >= 1 && o.minTrackLength <= o.maxTrackLength, "need 1 <= minTrackLength <= maxTrackLength");
  check(o.minTrackLength <= o.frames, "minTrackLength exceeds the number of frames");
  check(o.positionTolerance_m > 0.0 && o.angleTolerance_rad > 0.0, "bound tolerances must be positive");
  check(o.poseNoise_m >= 0.0 && o.poseNoise_rad >= 0.0 && o.pointNoise_m >= 0.0 && o.attitudeJitter_rad >= 0.0 &&
            o.heightJitter_m >= 0.0,
        "noise and jitter sigmas must be >= 0");
  check(o.startScale > 0.0, "startScale must be positive");
  check(o.fixedPoses >= 1 && o.fixedPoses <= o.frames, "fixedPoses must be in [1, frames]");
  check(o.deformation.allFinite(), "deformation must be finite");
}

// Mild rolling hills, |height| <= relief.
double terrainHeight(double x, double y, double relief) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return relief * (0.6 * std::sin(kTwoPi * x / 90.0 + 0.3) * std::cos(kTwoPi * y / 70.0) +
                   0.4 * std::sin(kTwoPi * (x + y) / 37.0));
}

// Camera x along world x (the flight), camera z down: columns are the camera axes in the world.
Eigen::Matrix3d levelWorldFromCamera() {
  Eigen::Matrix3d r;
  r << 1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0;
  return r;
}

Eigen::Isometry3d cameraFromWorld(const Eigen::Matrix3d& worldFromCamera, const Eigen::Vector3d& centre) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = worldFromCamera.transpose();
  pose.translation() = -pose.linear() * centre;
  return pose;
}

class Simulator {
 public:
  explicit Simulator(const WindowProblemOptions& options) : o_(options), rng_(options.seed) {
    const double focal = 0.5 * o_.imageWidth / std::tan(0.5 * o_.horizontalFov_deg * std::numbers::pi / 180.0);
    intrinsics_ = {focal, focal, 0.5 * o_.imageWidth, 0.5 * o_.imageHeight};
    calibrated_ << o_.baseline_m, 0.0, 0.0, 0.0, 0.0, 0.0;
    Vector6 deformation = o_.deformation;
    if (o_.trueOutsideBounds) {
      deformation[3] = 1.5 * o_.angleTolerance_rad;
      deformation[5] = -1.5 * o_.angleTolerance_rad;
    }
    trueExtrinsic_ = calibrated_ + deformation;
    secondaryRotation_ = rotationFromRollPitchYaw(trueExtrinsic_[3], trueExtrinsic_[4], trueExtrinsic_[5]);
  }

  WindowProblem build() {
    WindowProblem problem;
    problem.intrinsics = intrinsics_;
    problem.calibratedExtrinsic = calibrated_;
    problem.trueExtrinsic = trueExtrinsic_;
    problem.trueKappa = 1.0 / o_.startScale;
    simulatePoses(problem);
    std::vector<Track> tracks = simulatePoints(problem);
    addVertices(problem);
    addEdges(problem, tracks);
    return problem;
  }

 private:
  struct Track {
    int first;
    int length;
  };

  // A standard draw times sigma, so a zero sigma keeps the random stream as it is.
  double normal(double sigma) { return sigma * std::normal_distribution<double>(0.0, 1.0)(rng_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  Eigen::Vector3d normal3(double sigma) { return {normal(sigma), normal(sigma), normal(sigma)}; }

  void simulatePoses(WindowProblem& problem) {
    for (int i = 0; i < o_.frames; ++i) {
      const Eigen::Vector3d centre(i * o_.frameSpacing_m, 0.0, o_.altitude_m + normal(o_.heightJitter_m));
      const Eigen::Matrix3d attitude = expSO3(normal3(o_.attitudeJitter_rad)) * levelWorldFromCamera();
      problem.truePoses.push_back(cameraFromWorld(attitude, centre));
    }
  }

  // Both cameras' true projections of a world point in frame i; false when
  // behind a camera or outside the image's margin.
  bool visible(const Eigen::Isometry3d& pose, const Eigen::Vector3d& point, Eigen::Vector2d* base,
               Eigen::Vector2d* secondary) const {
    const Eigen::Vector3d inBase = pose * point;
    const Eigen::Vector3d inSecondary = secondaryRotation_ * (inBase - trueExtrinsic_.head<3>());
    if (inBase.z() <= 0.0 || inSecondary.z() <= 0.0) return false;
    *base = intrinsics_.project(inBase);
    *secondary = intrinsics_.project(inSecondary);
    return insideImage(*base, o_.imageMargin_px) && insideImage(*secondary, o_.imageMargin_px);
  }

  bool insideImage(const Eigen::Vector2d& pixel, double margin) const {
    return pixel.x() >= margin && pixel.x() <= o_.imageWidth - margin && pixel.y() >= margin &&
           pixel.y() <= o_.imageHeight - margin;
  }

  // Half the ground footprint along x (flight) and y at the highest terrain, nominal attitude.
  double halfFootprintX() const {
    return (o_.altitude_m - o_.terrainRelief_m) * (0.5 * o_.imageWidth - o_.imageMargin_px) / intrinsics_.fx;
  }
  double halfFootprintY() const {
    return (o_.altitude_m - o_.terrainRelief_m) * (0.5 * o_.imageHeight - o_.imageMargin_px) / intrinsics_.fy;
  }
  // Ground length along x seen by both cameras in every frame of a track of this length.
  double sharedFootprint(int length) const {
    return 2.0 * halfFootprintX() - (length - 1) * o_.frameSpacing_m - o_.baseline_m;
  }

  std::vector<Track> simulatePoints(WindowProblem& problem) {
    // A track must leave a tenth of the footprint to place its point in, so
    // that attitude jitter rarely pushes it out of an image.
    int longest = std::min(o_.maxTrackLength, o_.frames);
    while (longest >= o_.minTrackLength && sharedFootprint(longest) < 0.2 * halfFootprintX()) --longest;
    check(longest >= o_.minTrackLength, "the footprint at " + std::to_string(o_.altitude_m) + " m cannot hold a " +
                                            std::to_string(o_.minTrackLength) + "-frame track at " +
                                            std::to_string(o_.frameSpacing_m) + " m spacing");
    std::vector<Track> tracks;
    constexpr int kMaxAttempts = 1000;
    for (int j = 0; j < o_.points; ++j) {
      const int length = std::uniform_int_distribution<int>(o_.minTrackLength, longest)(rng_);
      const int first = std::uniform_int_distribution<int>(0, o_.frames - length)(rng_);
      const double xLow =
          problem.truePoses[first + length - 1].inverse().translation().x() + o_.baseline_m - halfFootprintX();
      const double xHigh = problem.truePoses[first].inverse().translation().x() + halfFootprintX();
      bool placed = false;
      for (int attempt = 0; attempt < kMaxAttempts && !placed; ++attempt) {
        const double x = uniform(xLow, xHigh), y = uniform(-halfFootprintY(), halfFootprintY());
        const Eigen::Vector3d point(x, y, terrainHeight(x, y, o_.terrainRelief_m));
        placed = true;
        Eigen::Vector2d base, secondary;
        for (int i = first; i < first + length && placed; ++i)
          placed = visible(problem.truePoses[i], point, &base, &secondary);
        if (placed) problem.truePoints.push_back(point);
      }
      check(placed, "could not place point " + std::to_string(j) + " in every image of frames " +
                        std::to_string(first) + ".." + std::to_string(first + length - 1) +
                        "; lower the attitude jitter or the track length");
      tracks.push_back({first, length});
    }
    return tracks;
  }

  void addVertices(WindowProblem& problem) {
    const int fixedPoses = std::max(o_.fixedPoses, o_.withScale ? 2 : 1);
    for (int i = 0; i < o_.frames; ++i) {
      const Eigen::Isometry3d worldFromCamera = problem.truePoses[i].inverse();
      Eigen::Vector3d centre = worldFromCamera.translation();
      Eigen::Matrix3d attitude = worldFromCamera.linear();
      const bool fixed = i < fixedPoses;
      if (!fixed) {
        centre += normal3(o_.poseNoise_m);
        attitude = expSO3(normal3(o_.poseNoise_rad)) * attitude;
      }
      auto pose = std::make_unique<VertexPose>(i, cameraFromWorld(attitude, o_.startScale * centre));
      pose->setFixed(fixed);
      problem.poses.push_back(problem.graph.addVertex(std::move(pose)));
    }
    int id = o_.frames;
    problem.extrinsic = problem.graph.addVertex(std::make_unique<VertexStereoExtrinsic>(id++, calibrated_));
    const Vector6 tolerance = (Vector6() << Eigen::Vector3d::Constant(o_.positionTolerance_m),
                               Eigen::Vector3d::Constant(o_.angleTolerance_rad))
                                  .finished();
    problem.extrinsicBounds.setAround(problem.extrinsic, calibrated_.data(), tolerance.data());
    if (o_.withScale) problem.scale = problem.graph.addVertex(std::make_unique<VertexScale>(id++, 1.0));
    for (const Eigen::Vector3d& point : problem.truePoints)
      problem.points.push_back(problem.graph.addVertex(
          std::make_unique<VertexPoint3>(id++, o_.startScale * (point + normal3(o_.pointNoise_m)))));
  }

  template <typename EdgeType>
  void addEdge(WindowProblem& problem, std::unique_ptr<EdgeType> edge, const Eigen::Vector2d& truth) {
    // Noise is redrawn in the (at 1 px noise and a 10 px margin, never seen)
    // case that it pushes a measurement out of the image.
    Eigen::Vector2d measurement;
    do {
      measurement = truth + Eigen::Vector2d(normal(o_.pixelNoise), normal(o_.pixelNoise));
    } while (!insideImage(measurement, 0.0));
    edge->setMeasurement(measurement);
    edge->setInformation(Eigen::Matrix2d::Identity() / (o_.measurementSigma * o_.measurementSigma));
    if (!o_.robustKernel.empty()) edge->setRobustKernel(makeRobustKernel(o_.robustKernel, o_.robustKernelDelta));
    problem.graph.addEdge(std::move(edge));
  }

  void addEdges(WindowProblem& problem, const std::vector<Track>& tracks) {
    const SecondaryCamera camera{1, intrinsics_};
    for (std::size_t j = 0; j < tracks.size(); ++j) {
      for (int i = tracks[j].first; i < tracks[j].first + tracks[j].length; ++i) {
        Eigen::Vector2d base, secondary;
        visible(problem.truePoses[i], problem.truePoints[j], &base, &secondary);
        auto baseEdge = std::make_unique<EdgeProjectBase>(intrinsics_);
        baseEdge->setVertex(0, problem.poses[i]);
        baseEdge->setVertex(1, problem.points[j]);
        addEdge(problem, std::move(baseEdge), base);
        if (problem.scale) {
          auto edge = std::make_unique<EdgeProjectSecondaryScaled>(camera);
          edge->setVertex(3, problem.scale);
          addSecondary(problem, std::move(edge), i, j, secondary);
        } else {
          addSecondary(problem, std::make_unique<EdgeProjectSecondary>(camera), i, j, secondary);
        }
      }
    }
  }

  template <typename EdgeType>
  void addSecondary(WindowProblem& problem, std::unique_ptr<EdgeType> edge, int i, std::size_t j,
                    const Eigen::Vector2d& truth) {
    edge->setVertex(0, problem.poses[i]);
    edge->setVertex(1, problem.points[j]);
    edge->setVertex(2, problem.extrinsic);
    addEdge(problem, std::move(edge), truth);
  }

  const WindowProblemOptions& o_;
  std::mt19937_64 rng_;
  PinholeIntrinsics intrinsics_;
  Vector6 calibrated_;
  Vector6 trueExtrinsic_;
  Eigen::Matrix3d secondaryRotation_;
};

}  // namespace

WindowProblem makeWindowProblem(const WindowProblemOptions& options) {
  validate(options);
  return Simulator(options).build();
}

double estimatedMapScale(const WindowProblem& problem) {
  const Eigen::Vector3d trueFirst = problem.truePoses.front().inverse().translation();
  const Eigen::Vector3d trueLast = problem.truePoses.back().inverse().translation();
  return (problem.poses.back()->centre() - problem.poses.front()->centre()).norm() / (trueLast - trueFirst).norm();
}

}  // namespace lrsvo
