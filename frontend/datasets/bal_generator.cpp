#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/Geometry>

#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

namespace {

// The scene: a block of points (a building seen from a drone circling it)
// inside |x|, |y| <= kSceneHalfWidth, |z| <= kSceneHalfHeight, and cameras on
// a ring of radius kRingRadius at height kRingHeight, each displaced by up to
// kJitter per axis and aimed within kJitter of the scene centre. Every point
// then lies 6 m or more in front of every camera and within about 25 degrees of
// its optical axis, so every observation is a valid image point. At this scale
// the default start perturbations cost a few pixels, as in the published sets.
constexpr double kSceneHalfWidth = 3.0;
constexpr double kSceneHalfHeight = 1.0;
constexpr double kRingRadius = 12.0;
constexpr double kRingHeight = 3.6;
constexpr double kJitter = 0.6;

void checkOptions(const BalGeneratorOptions& o) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw Error("BAL generator: " + what);
  };
  require(o.cameras >= 2, "needs at least 2 cameras, got " + std::to_string(o.cameras));
  require(o.points >= 1, "needs at least 1 point, got " + std::to_string(o.points));
  require(o.observationsPerPoint >= 2,
          "needs at least 2 observations per point, got " + std::to_string(o.observationsPerPoint));
  require(static_cast<long long>(o.cameras) + o.points <= 1'000'000'000, "too many cameras and points");
  for (double sigma : {o.pixelNoise, o.rotationNoise, o.translationNoise, o.pointNoise})
    require(sigma >= 0.0 && std::isfinite(sigma), "noise sigmas must be finite and not negative");
}

// Camera-from-world rotation of a camera at `centre` looking at `target`. The
// BAL camera looks down its -z axis; x points right, y up (world +z is up).
Eigen::Matrix3d lookAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& target, double roll) {
  const Eigen::Vector3d z = (centre - target).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitZ().cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d worldToCamera;
  worldToCamera << x.transpose(), y.transpose(), z.transpose();
  return Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix() * worldToCamera;
}

Eigen::Vector3d angleAxisOf(const Eigen::Matrix3d& rotation) {
  const Eigen::AngleAxisd angleAxis(rotation);
  return angleAxis.angle() * angleAxis.axis();
}

// Draws scale a standard normal, so a zero sigma is allowed and the random
// stream does not depend on the sigmas.
class Gaussian {
 public:
  explicit Gaussian(std::mt19937_64& random) : random_(random) {}
  double operator()(double sigma) { return sigma * standard_(random_); }
  Eigen::Vector3d vector3(double sigma) {
    const double x = (*this)(sigma), y = (*this)(sigma), z = (*this)(sigma);
    return {x, y, z};
  }

 private:
  std::mt19937_64& random_;
  std::normal_distribution<double> standard_{0.0, 1.0};
};

}  // namespace

BalProblem generateBalProblem(const BalGeneratorOptions& options) {
  checkOptions(options);
  std::mt19937_64 random(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Gaussian gaussian(random);
  BalProblem problem;

  // True cameras: evenly spaced on the ring with jitter in place and aim,
  // focal length 500-1000 px, mild radial distortion.
  problem.cameras.resize(options.cameras);
  for (int i = 0; i < options.cameras; ++i) {
    const double azimuth = 2.0 * std::numbers::pi * (i + 0.3 * unit(random)) / options.cameras;
    const Eigen::Vector3d centre(kRingRadius * std::cos(azimuth) + kJitter * unit(random),
                                 kRingRadius * std::sin(azimuth) + kJitter * unit(random),
                                 kRingHeight + kJitter * unit(random));
    const Eigen::Vector3d target(kJitter * unit(random), kJitter * unit(random), kJitter * unit(random));
    const Eigen::Matrix3d rotation = lookAt(centre, target, 0.05 * unit(random));
    auto& camera = problem.cameras[i];
    camera.head<3>() = angleAxisOf(rotation);
    camera.segment<3>(3) = -rotation * centre;
    camera[6] = 750.0 + 250.0 * unit(random);
    camera[7] = 0.05 * unit(random);
    camera[8] = 0.01 * unit(random);
  }

  // True points, each seen by a run of neighbouring cameras on the ring (as
  // a track in a sequence): 2 + Poisson(mean - 2) cameras, at most all of them
  // (so with few cameras the mean falls short of the one asked for).
  problem.points.resize(options.points);
  problem.observations.reserve(static_cast<std::size_t>(options.points) * options.observationsPerPoint);
  std::poisson_distribution<int> extraViews(options.observationsPerPoint - 2.0);
  std::uniform_int_distribution<int> firstCamera(0, options.cameras - 1);
  for (int j = 0; j < options.points; ++j) {
    problem.points[j] = Eigen::Vector3d(kSceneHalfWidth * unit(random), kSceneHalfWidth * unit(random),
                                        kSceneHalfHeight * unit(random));
    const int views = std::min(options.cameras, 2 + (options.observationsPerPoint > 2 ? extraViews(random) : 0));
    const int first = firstCamera(random);
    for (int v = 0; v < views; ++v) {
      const int camera = (first + v) % options.cameras;
      const Eigen::Vector2d pixel = projectBal(problem.cameras[camera], problem.points[j]);
      const double noiseX = gaussian(options.pixelNoise), noiseY = gaussian(options.pixelNoise);
      problem.observations.push_back({camera, j, pixel + Eigen::Vector2d(noiseX, noiseY)});
    }
  }

  // The start: the truth perturbed, as the published BAL sets are noisy starts.
  for (auto& camera : problem.cameras) {
    camera.head<3>() += gaussian.vector3(options.rotationNoise);
    camera.segment<3>(3) += gaussian.vector3(options.translationNoise);
  }
  for (auto& point : problem.points) point += gaussian.vector3(options.pointNoise);
  return problem;
}

}  // namespace lrsvo
