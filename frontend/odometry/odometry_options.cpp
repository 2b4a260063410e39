#include "lrsvo/frontend/odometry/odometry_options.h"

#include <cmath>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/solver_options.h"

namespace lrsvo {

ExtrinsicMode extrinsicModeFromName(const std::string& name) {
  if (name == "bounded") return ExtrinsicMode::kBounded;
  if (name == "free") return ExtrinsicMode::kFree;
  if (name == "rigid") return ExtrinsicMode::kRigid;
  throw Error("unknown extrinsic mode '" + name + "' (expected bounded, free or rigid)");
}

const char* extrinsicModeName(ExtrinsicMode mode) {
  switch (mode) {
    case ExtrinsicMode::kBounded: return "bounded";
    case ExtrinsicMode::kFree: return "free";
    case ExtrinsicMode::kRigid: return "rigid";
  }
  return "?";
}

void OdometryOptions::validate() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw Error("odometry options: " + what);
  };
  require(windowSize >= 3, "windowSize must be at least 3, got " + std::to_string(windowSize));
  require(fixedPoses >= 1 && fixedPoses < windowSize, "fixedPoses must be in [1, windowSize)");
  require(anchorKeyframes >= 0, "anchorKeyframes must not be negative");
  require(scaleDriftPerKeyframe >= 0.0, "scaleDriftPerKeyframe must not be negative");
  require(extrinsicRateSigma >= 0.0 && std::isfinite(extrinsicRateSigma),
          "extrinsicRateSigma must be finite and not negative");
  require(initializer.frames <= windowSize, "the initialiser's frames must fit the window");
  require(maxInitializationFrames >= initializer.frames,
          "maxInitializationFrames must be at least the initialiser's frames");
  require(solver.maxIterations >= 1, "solver.maxIterations must be positive");
  lrsvo::validate(outliers);
  require(minTriangulationViews >= 2, "minTriangulationViews must be at least 2");
  require(minPoseInliers >= 4, "minPoseInliers must be at least 4");
  require(maxPrediction_s >= 0.0 && std::isfinite(maxPrediction_s), "maxPrediction_s must be finite and >= 0");
  require(relocaliseWithin_s >= 0.0 && std::isfinite(relocaliseWithin_s), "relocaliseWithin_s must be finite and >= 0");
  require(initializationInterval_s >= 0.0 && std::isfinite(initializationInterval_s),
          "initializationInterval_s must be finite and >= 0");
  stereoStart.validate();
  require(keyframes.maxInterval_s > 0.0 && std::isfinite(keyframes.maxInterval_s),
          "keyframes.maxInterval_s must be finite and > 0");
  require(keyframes.minInterval_s >= 0.0 && keyframes.minInterval_s <= keyframes.maxInterval_s,
          "keyframes.minInterval_s must lie in [0, keyframes.maxInterval_s]");
  try {
    (void)makeConstraintMethod(constraintMethod);
  } catch (const Error& e) {
    require(false, e.what());
  }
  solver.validate();
}

}  // namespace lrsvo
