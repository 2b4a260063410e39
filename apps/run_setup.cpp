#include "apps/run_setup.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "lrsvo/frontend/datasets/source_factory.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/sim/scenario.h"
#include "lrsvo/sim/sim_frame_source.h"

namespace lrsvo::cli {
namespace {

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

void OdometrySettings::addOptions(CLI::App& command) {
  command
      .add_option("--constraint", constraint,
                  "How the stereo extrinsic S is kept inside its bounds in the window adjustment, as "
                  "name[:setting=value,...]: log_barrier (the paper's), gradient_projection, nlopt_lbfgs, nlopt_mma, "
                  "or none (S free: the paper's unconstrained comparison); settings not named keep the method's "
                  "defaults (`lrsvo solvers` lists them), e.g. log_barrier:mu=0.001,rounds=2")
      ->capture_default_str();
  command.add_flag("--rigid", rigid, "Hold S at its calibration (conventional rigid stereo VO, the failing baseline)");
  command.add_option("--window", window, "Keyframes in the sliding window (paper: 12-15)")
      ->check(CLI::Range(3, 100))
      ->capture_default_str();
  command
      .add_option("--anchors", anchors,
                  "Retired keyframes held in each window adjustment: fixed views whose observations keep the window's "
                  "map from tilting and rescaling (0: the window alone)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  command
      .add_option("--scale-drift", scaleDrift,
                  "Relative scale drift allowed per keyframe: the process noise of the scale the held keyframes carry "
                  "from window to window")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      .add_option("--extrinsic-rate", extrinsicRate,
                  "Prior std of how fast S changes, in its bound half-widths per second: each window estimates S "
                  "and its rate, so a rig flexing within the window is followed (0: one constant S per window, the "
                  "paper's model)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      .add_option("--max-keyframe-rate", maxKeyframeRate_hz,
                  "Most keyframes a second (each costs a window adjustment); keyframes otherwise follow the image "
                  "motion. 0: no limit, every frame may be a keyframe")
      ->check(CLI::Validator(
          [](const std::string& text) {
            const KeyframePolicyOptions defaults;
            char* end = nullptr;
            const double rate_hz = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0') return std::string("must be a number of keyframes a second");
            return rate_hz == 0.0 || rate_hz * defaults.maxInterval_s >= 1.0 - 1e-9
                       ? std::string()
                       : "must be 0 or at least " + formatNumber(1.0 / defaults.maxInterval_s) +
                             " (a keyframe comes at least every " + formatNumber(defaults.maxInterval_s) + " s)";
          },
          ""))
      ->capture_default_str();
  command.add_option("--detector", detector, "Feature detector: gftt or fast (KLT tracking), orb (descriptors)")
      ->capture_default_str();
  command.add_option("--features", features, "Features kept per frame (new ones detected below this)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      .add_option("--band", band_px,
                  "Half-width in pixels of the loosened epipolar band stereo matches must lie in (a flexed rig moves "
                  "the epipolar lines)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      .add_option("--min-depth", minDepth_m,
                  "Nearest depth (m) the stereo matcher searches for: it bounds the disparity range (20 m suits a "
                  "flight at 30-120 m; a room-scale data set such as EuRoC needs ~0.5)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      .add_option("--outlier-sigmas", outlierSigmas,
                  "After each window adjustment, observations farther than this many times the window's own noise "
                  "(from its median reprojection error; within 0.5-4 px) are removed (0: a fixed 4 px)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command.add_option("--solver", solver, "Solver of the window adjustment (lrsvo solvers lists them)")
      ->capture_default_str();
  command
      .add_option("--threads", threads,
                  "Threads of the window adjustment; the estimates are the same for any count, bit for bit")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--seed", seed, "Seed of every random draw (RANSAC, MLESAC)")->capture_default_str();
  command
      .add_option("--on-bad-frame", onBadFrame,
                  "A frame whose images cannot be used (missing, undecodable, blank, wrongly sized): skip gives it no "
                  "pose, says why in frames.csv and goes on; stop ends the run with an error")
      ->check(CLI::IsMember({"skip", "stop"}))
      ->capture_default_str();
}

RunOptions OdometrySettings::runOptions() const {
  RunOptions options;
  OdometryOptions& odometry = options.odometry;
  odometry.windowSize = window;
  odometry.anchorKeyframes = anchors;
  odometry.scaleDriftPerKeyframe = scaleDrift;
  odometry.extrinsicRateSigma = extrinsicRate;
  odometry.keyframes.minInterval_s = maxKeyframeRate_hz > 0.0 ? 1.0 / maxKeyframeRate_hz : 0.0;
  odometry.solver.setName(solver);
  odometry.solver.threads = threads;
  odometry.seed = seed;
  odometry.outliers.sigmas = outlierSigmas;
  if (rigid)
    odometry.extrinsicMode = ExtrinsicMode::kRigid;
  else if (constraintMethodName(constraint) == "none")
    odometry.extrinsicMode = ExtrinsicMode::kFree;
  else
    odometry.constraintMethod = constraint;
  odometry.validate();
  options.frontEnd.tracker.detector.name = detector;
  options.frontEnd.tracker.targetFeatures = features;
  options.frontEnd.stereo.bandWidth_px = band_px;
  options.frontEnd.stereo.minDepth_m = minDepth_m;
  options.frontEnd.seed = seed;
  options.onBadFrame = badFramePolicyFromName(onBadFrame);
  return options;
}

std::unique_ptr<FrameSource> openSource(const std::string& spec) {
  if (spec.rfind("sim:", 0) == 0) return makeSimSource(spec.substr(4));
  return openDatasetSource(spec);
}

FeatureLevelFlight simulateFeatureLevel(const std::string& spec) {
  if (spec.rfind("sim:", 0) != 0)
    throw Error("--feature-level needs a sim: source (sim:demo, sim:paper, sim:stress, sim:FILE.yaml), not '" + spec +
                "'");
  const SimScenario scenario = loadScenario(spec.substr(4));
  SimulatedSequence sequence = simulateSequence(featureSimulationOptions(scenario));
  FeatureLevelFlight flight{spec + " (feature level)", sequence.rig, std::move(sequence.frames), {}};
  for (std::size_t i = 0; i < sequence.trueCameraFromWorld.size(); ++i)
    flight.truth.poses.push_back({flight.frames[i].time_s, sequence.trueCameraFromWorld[i].inverse()});
  flight.truth.extrinsics = std::move(sequence.trueExtrinsics);
  return flight;
}

SourceRun runSource(const std::string& spec, const RunOptions& options, bool featureLevel,
                    const std::function<void(const std::string& name, int frames, const Rig& rig)>& onStart) {
  SourceRun result;
  if (featureLevel) {
    FeatureLevelFlight flight = simulateFeatureLevel(spec);
    if (onStart)
      onStart(flight.name, framesInRun(static_cast<int>(flight.frames.size()), options.firstFrame, options.maxFrames),
              flight.rig);
    result.run = std::move(runOdometry(flight.rig, flight.frames, flight.truth, {options}).front());
    result.truth = std::move(flight.truth);
  } else {
    std::unique_ptr<FrameSource> source = openSource(spec);
    if (onStart)
      onStart(source->name(), framesInRun(source->frameCount(), options.firstFrame, options.maxFrames), source->rig());
    result.run = runOdometry(*source, options);
    result.truth = source->groundTruth();
  }
  return result;
}

std::string folderName(const std::string& spec) {
  std::string name = spec;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return c == ':' || c == '/' || c == '.'; }, '_');
  name.erase(0, name.find_first_not_of('_'));
  return name.empty() ? "run" : name;
}

}  // namespace lrsvo::cli
