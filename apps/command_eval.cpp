// `lrsvo eval ESTIMATE GROUNDTRUTH`: the trajectory metrics of an estimate
// against the truth (ATE, RPE, KITTI drift, scale and end-point error), as a
// table, metrics.json and plots.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>

#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "lrsvo/eval/trajectory_metrics.h"
#include "lrsvo/eval/trajectory_plots.h"
#include "lrsvo/frontend/datasets/pose_file.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo::cli {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

struct EvalCommandOptions {
  std::string estimate, truth;
  std::string format = "auto";
  std::string times;
  int delta = 1;
  double deltaMeters = 100.0;
  bool allPairs = false;
  std::string rpePath = "estimate";
  std::vector<double> segmentLengths = kittiSegmentLengths();
  double maxTimeDifference = 0.02;
  std::string out = "lrsvo_eval";
  bool noPlot = false;
};

PoseFileFormat formatOf(const EvalCommandOptions& o, const std::string& file) {
  return o.format == "auto" ? detectPoseFileFormat(file) : poseFileFormatFromName(o.format);
}

Trajectory readTrajectory(const std::string& file, PoseFileFormat format, const std::string& times) {
  return format == PoseFileFormat::kTum ? readTumTrajectory(file) : readKittiTrajectory(file, times);
}

void printRow(const char* name, double value, const char* unit) {
  std::printf("  %-40s %12.4f  %s\n", name, value, unit);
}

void printStatistics(const std::string& name, const ErrorStatistics& s, double factor, const char* unit) {
  std::printf("  %-40s %12.4f  %s  (mean %.4f, median %.4f, max %.4f)\n", (name + " RMSE").c_str(), factor * s.rmse,
              unit, factor * s.mean, factor * s.median, factor * s.max);
}

void printMetrics(const TrajectoryMetrics& m) {
  std::printf("  %-40s %12zu\n", "matched poses", m.frames);
  printRow("distance (truth path length)", m.distance_m, "m");
  printStatistics("ATE, SE3-aligned", m.ate_m, 1.0, "m");
  printStatistics("ATE orientation, SE3-aligned", m.ateRotation_rad, kDegreesPerRadian, "deg");
  printStatistics("ATE, Sim3-aligned", m.ateSim3_m, 1.0, "m");
  printRow("Sim3 scale", m.sim3.scale, "");
  const std::string frames = "RPE, delta " + std::to_string(m.options.rpeDeltaFrames) + " frame(s)";
  printStatistics(frames + ", translation", m.rpeTranslation_m, 1.0, "m");
  printStatistics(frames + ", rotation", m.rpeRotation_rad, kDegreesPerRadian, "deg");
  char metres[64];
  std::snprintf(metres, sizeof metres, "RPE, delta %g m", m.options.rpeDelta_m);
  if (m.rpeDistanceTranslation_m.count > 0) {
    printStatistics(std::string(metres) + ", translation", m.rpeDistanceTranslation_m, 1.0, "m");
    printStatistics(std::string(metres) + ", rotation", m.rpeDistanceRotation_rad, kDegreesPerRadian, "deg");
  } else {
    std::printf("  %-40s %12s  (the truth is shorter)\n", metres, "-");
  }
  if (m.drift.segments > 0) {
    printRow("KITTI drift, translation", m.drift.translation_percent, "%");
    printRow("KITTI drift, rotation", m.drift.rotation_deg_per_100m, "deg/100 m");
    for (const DriftAtLength& d : m.drift.perLength)
      std::printf("    %5.0f m segments (%4zu)  %8.4f %%  %8.4f deg/100 m\n", d.length_m, d.segments,
                  d.translation_percent, d.rotation_deg_per_100m);
  } else {
    std::printf("  %-40s %12s  (no segment length fits the truth)\n", "KITTI drift", "-");
  }
  printRow("scale error (Sim3)", m.scaleErrorPercent, "%");
  printRow("path length error", m.pathLengthErrorPercent, "%");
  printRow("final position error, start-aligned", m.finalPositionError_m, "m");
  printRow("  of the distance", m.finalPositionErrorPercent, "%");
}

void runEvalCommand(const EvalCommandOptions& o) {
  const Stopwatch start;
  const PoseFileFormat estimateFormat = formatOf(o, o.estimate);
  const PoseFileFormat truthFormat = formatOf(o, o.truth);
  const bool byIndex = estimateFormat == PoseFileFormat::kKitti && truthFormat == PoseFileFormat::kKitti;
  if (!byIndex && o.times.empty() &&
      (estimateFormat == PoseFileFormat::kKitti || truthFormat == PoseFileFormat::kKitti))
    throw Error("a KITTI pose file matched by time against a TUM one needs its times: give --times FILE");
  const Trajectory estimate = readTrajectory(o.estimate, estimateFormat, o.times);
  const Trajectory truth = readTrajectory(o.truth, truthFormat, o.times);
  const AssociatedTrajectories matched =
      byIndex ? associateByIndex(estimate, truth) : associateByTime(estimate, truth, o.maxTimeDifference);
  if (matched.estimate.size() < 2)
    throw Error("only " + std::to_string(matched.estimate.size()) + " of " + std::to_string(estimate.size()) +
                " estimated poses match a true one within " + std::to_string(o.maxTimeDifference) +
                " s; expected at least 2 (check the time stamps or --max-time-difference)");

  TrajectoryMetricsOptions options;
  options.rpeDeltaFrames = o.delta;
  options.rpeDelta_m = o.deltaMeters;
  options.rpeAllPairs = o.allPairs;
  options.rpePath = o.rpePath == "truth" ? RpePath::kTruth : RpePath::kEstimate;
  options.driftLengths_m = o.segmentLengths;
  const TrajectoryMetrics metrics = computeTrajectoryMetrics(matched, options);

  const std::filesystem::path outDir(o.out);
  std::filesystem::create_directories(outDir);
  nlohmann::json json = toJson(metrics);
  json["estimate_file"] = o.estimate;
  json["truth_file"] = o.truth;
  json["association"] = byIndex ? "index" : "time";
  if (!byIndex) json["max_time_difference_s"] = o.maxTimeDifference;
  json["estimate_poses"] = estimate.size();
  json["truth_poses"] = truth.size();
  const std::filesystem::path jsonFile = outDir / "metrics.json";
  std::ofstream jsonOut(jsonFile);
  if (!(jsonOut << json.dump(2) << '\n')) throw Error("cannot write " + jsonFile.string());
  const bool timesKnown = !byIndex || !o.times.empty();
  const std::filesystem::path table = writeTrajectoryTable(outDir, matched, metrics, timesKnown);
  const TrajectoryPlots plots = o.noPlot ? TrajectoryPlots{} : plotTrajectory(outDir);
  const double seconds = start.seconds();

  std::printf("%s against %s (%zu of %zu estimated poses matched by %s)\n", o.estimate.c_str(), o.truth.c_str(),
              metrics.frames, estimate.size(), byIndex ? "index" : "time");
  printMetrics(metrics);
  std::printf("  wrote %s, %s", jsonFile.string().c_str(), table.string().c_str());
  for (const auto& png : plots.files) std::printf(", %s", png.string().c_str());
  std::printf(" (%.2f s)\n", seconds);
  std::fflush(stdout);
  if (!plots.warning.empty()) std::cerr << "lrsvo eval: warning: " << plots.warning << '\n';
}

const char* kEvalFooter =
    "Metrics (docs/evaluation.md gives the formulas; P_i estimated, Q_i true poses world-from-camera):\n"
    "  ATE          position error |q_i - (s R p_i + t)| after Umeyama's least-squares alignment of the\n"
    "               positions: SE3 (s = 1) and, apart, Sim3 (scale s estimated, reported as sim3_scale).\n"
    "               RMSE, mean, median, max in m; orientation error angle(R_q^T R R_p) in deg.\n"
    "  RPE          E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), |t(E)| (m) and angle(E) (deg), over evo's pairs: j = i +\n"
    "               delta frames (--delta), or by --delta-m metres of path along the estimate (--rpe-path):\n"
    "               chained, between the frames where the path walked since the last one reaches the step\n"
    "               (the first where it first does), or with --all-pairs from every frame to the one whose\n"
    "               path length from it is nearest the step, within 10 %. On the raw estimate.\n"
    "  KITTI drift  the devkit's evaluate_odometry: segments of 100, 200, ..., 800 m (--segment-lengths)\n"
    "               starting every 10th frame; per segment |t(E)| / length and angle(E) / length; the\n"
    "               average over all segments in % and deg/100 m, and per length.\n"
    "  scale error  100 (L_estimate / L_truth - 1) of the path lengths, in %.\n"
    "  final error  distance between the last poses after putting the first estimated pose on the\n"
    "               first true one (start-aligned end-point drift), in m and % of the distance.\n"
    "Files: pose files are TUM (t tx ty tz qx qy qz qw) or KITTI (12 numbers, 3x4 [R|t] row by row).\n"
    "Two KITTI files are matched by index (same length), anything else by time stamp: nearest stamps at most\n"
    "--max-time-difference apart, each pose used once. Writes OUT/metrics.json, OUT/trajectory.csv and,\n"
    "with python3-matplotlib, trajectory_top.png, position_error.png, orientation_error.png.";

void addEvalCommand(CLI::App& app) {
  auto options = std::make_shared<EvalCommandOptions>();
  CLI::App* command = app.add_subcommand("eval",
                                         "Trajectory metrics of an estimate against the truth (ATE, RPE, "
                                         "KITTI drift, scale), as a table, metrics.json and plots");
  command->footer(kEvalFooter);
  command->add_option("estimate", options->estimate, "Estimated trajectory (TUM or KITTI pose file)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("groundtruth", options->truth, "True trajectory (TUM or KITTI pose file)")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--format", options->format,
                   "Format of both files: tum, kitti, or auto (by the count of numbers on the first pose line)")
      ->check(CLI::IsMember({"auto", "tum", "kitti"}))
      ->capture_default_str();
  command
      ->add_option("--times", options->times,
                   "Times file of KITTI poses (one time in s a line, as many as poses); without it a KITTI pose's "
                   "time is its index")
      ->check(CLI::ExistingFile);
  command->add_option("--delta", options->delta, "RPE step in frames")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--delta-m", options->deltaMeters, "RPE step in metres of path (along --rpe-path)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_flag("--all-pairs", options->allPairs, "RPE: a pair at every frame instead of chained pairs");
  command
      ->add_option("--rpe-path", options->rpePath,
                   "Whose path --delta-m is measured along: estimate (evo's rule) or truth")
      ->check(CLI::IsMember({"estimate", "truth"}))
      ->capture_default_str();
  command
      ->add_option("--segment-lengths", options->segmentLengths,
                   "KITTI drift segment lengths in m, comma-separated (lengths longer than the truth are skipped)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      ->add_option("--max-time-difference", options->maxTimeDifference, "Largest time difference (s) of matched stamps")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--out", options->out, "Output folder for metrics.json, trajectory.csv and plots")
      ->capture_default_str();
  command->add_flag("--no-plot", options->noPlot, "Write metrics.json and trajectory.csv only, no PNG");
  command->callback([options] { runEvalCommand(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("eval", addEvalCommand);

}  // namespace lrsvo::cli
