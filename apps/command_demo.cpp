// `lrsvo demo`: the project's default job: a synthetic long-range flight. A
// stereo rig with a 0.7 m baseline flies 60 m at 100 m above farmland with a
// rig that has flexed since its calibration; the long-range initialisation
// (monocular start, then kappa and the bounded extrinsic) recovers metric
// poses, and the conventional rigid-stereo start runs beside it.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/command.h"
#include "eval/initialization_trial.h"
#include "frontend/long_range_initializer.h"
#include "frontend/rigid_stereo_initializer.h"
#include "graph/error.h"

namespace lrsvo::cli {
namespace {

// The verdict: the initialiser must call its result sound, and the scale
// error must lie within this many of the standard deviations it reports.
constexpr double kConsistencySigmas = 3.0;

struct DemoOptions {
  InitializationFlight flight;
  std::string constraintMethod = "log_barrier";
};

void printExtrinsics(const SimulatedSequence& sequence, const InitializationResult& result) {
  const VertexStereoExtrinsic::Vector6& calibration = sequence.rig.extrinsics[0];
  VertexStereoExtrinsic::Vector6 truth = VertexStereoExtrinsic::Vector6::Zero();
  for (const auto& frame : sequence.trueExtrinsics) truth += frame[0] / sequence.trueExtrinsics.size();
  const VertexStereoExtrinsic::Vector6& tolerance = sequence.rig.tolerance;
  std::printf(
      "  stereo extrinsic, change from calibration   x (mm)   y (mm)   z (mm)   about x (mrad) about y (mrad) about z "
      "(mrad)\n");
  auto row = [](const char* what, const VertexStereoExtrinsic::Vector6& d) {
    std::printf("    %-40s %8.3f %8.3f %8.3f %16.3f %14.3f %14.3f\n", what, 1e3 * d[0], 1e3 * d[1], 1e3 * d[2],
                1e3 * d[3], 1e3 * d[4], 1e3 * d[5]);
  };
  row("true (mean over the frames)", truth - calibration);
  if (!result.extrinsics.empty()) row("estimated", result.extrinsics[0] - calibration);
  row("bound (+-)", tolerance);
}

void runDemo(const DemoOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  InitializationFlight flight = o.flight;
  flight.speed_m_s = paperSpeedForAltitude(flight.altitude_m);
  const SimulatedSequence sequence = simulateSequence(initializationSimulation(flight));
  std::printf(
      "Demo: a synthetic long-range flight (seed %llu): %.0f m above ground at %.0f m/s, %d frames, 0.7 m stereo "
      "baseline, 1024x768, f = %.0f px, %d features per frame, %.1f px noise, rig flexed within %.0f %% of its "
      "bounds\n",
      static_cast<unsigned long long>(flight.seed), flight.altitude_m, flight.speed_m_s, flight.frames,
      sequence.rig.cameras[0].intrinsics.fx, flight.pointsPerFrame, flight.pixelNoise_px, 100.0 * flight.flexFraction);

  LongRangeInitializerOptions longRange;
  longRange.constraintMethod = o.constraintMethod;
  longRange.seed = flight.seed;
  const InitializationResult ours = LongRangeInitializer(longRange).initialize(sequence.rig, sequence.frames);
  const InitializationScore score = scoreInitialization(sequence, flight.frames, ours);
  RigidStereoInitializerOptions rigidOptions;
  rigidOptions.seed = flight.seed;
  const InitializationResult rigid = RigidStereoInitializer(rigidOptions).initialize(sequence.rig, sequence.frames);
  const InitializationScore rigidScore = scoreInitialization(sequence, flight.frames, rigid);

  std::printf("\nLong-range initialisation (%s): %s\n", o.constraintMethod.c_str(),
              ours.success ? "sound" : ("not sound: " + ours.failure).c_str());
  std::printf("  batch adjustment: %s\n", ours.summary.briefReport().c_str());
  std::printf("  kappa %.4f (map unit in metres), relative std %.2f %%, RMS reprojection %.3f px\n", ours.kappa,
              100.0 * ours.kappaRelativeStd, ours.rmsReprojectionError_px);
  printExtrinsics(sequence, ours);
  const double scaleError = score.scaleRatio - 1.0;
  std::printf("  over %.1f m flown: final camera %.2f m from the truth (%.2f %%), scale error %+.2f %%\n",
              score.distanceFlown_m, score.finalPositionError_m,
              100.0 * score.finalPositionError_m / score.distanceFlown_m, 100.0 * scaleError);
  std::printf("\nRigid-stereo start (the paper's control, extrinsic held at calibration): %s\n",
              rigid.success ? "completed" : ("failed: " + rigid.failure).c_str());
  std::printf("  final camera %.2f m from the truth (%.2f %% of the distance flown)\n", rigidScore.finalPositionError_m,
              100.0 * rigidScore.finalPositionError_m / rigidScore.distanceFlown_m);

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool consistent =
      std::isfinite(scaleError) && std::abs(scaleError) <= kConsistencySigmas * ours.kappaRelativeStd;
  const bool sound = ours.success && consistent;
  std::printf(
      "\nVerdict: %s: long-range start %s, scale error %+.2f %% against %.0f x its reported %.2f %% std; %.2f s in "
      "all\n",
      sound ? "OK" : "FAILED", ours.success ? "sound" : "not sound", 100.0 * scaleError, kConsistencySigmas,
      100.0 * ours.kappaRelativeStd, seconds);
  std::fflush(stdout);
  if (!sound)
    throw Error("demo: the long-range initialisation is not sound or not consistent with its own uncertainty");
}

void addDemoCommand(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* command = app.add_subcommand(
      "demo",
      "A synthetic long-range flight: the long-range initialisation (kappa, bounded extrinsic) against a "
      "rigid-stereo start, scored against the ground truth");
  command->footer(
      "Exits with status 1 when the long-range start is not sound or its scale error exceeds 3 times the standard "
      "deviation it reports. For the paper's studies use `lrsvo study`, for a BAL problem `lrsvo bal --generate`.");
  command->add_option("--altitude", options->flight.altitude_m, "Height above ground (m)")
      ->check(CLI::Range(10.0, 1000.0))
      ->capture_default_str();
  command->add_option("--frames", options->flight.frames, "Frames of the initialisation, over up to 60 m")
      ->check(CLI::Range(3, 50))
      ->capture_default_str();
  command
      ->add_option("--flex", options->flight.flexFraction,
                   "Rig flex since calibration, as a fraction of the bounds (1 mm, 0.01 rad)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--noise", options->flight.pixelNoise_px, "Pixel noise sigma (px)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  command
      ->add_option("--method", options->constraintMethod,
                   "Constraint method on the extrinsic (none, log_barrier, gradient_projection, nlopt_lbfgs, ...)")
      ->capture_default_str();
  command->add_option("--seed", options->flight.seed, "Random seed of the world, flight, rig flex and noise")
      ->capture_default_str();
  command->callback([options] { runDemo(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("demo", addDemoCommand);

}  // namespace lrsvo::cli
