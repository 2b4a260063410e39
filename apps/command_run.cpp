// `lrsvo run SOURCE`: the long-range stereo odometry on a sequence of images.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "apps/command.h"
#include "apps/run_setup.h"
#include "apps/stop_on_signal.h"
#include "lrsvo/eval/run_report.h"

namespace lrsvo::cli {
namespace {

struct RunCommandOptions {
  std::string source;
  std::string out;
  int first = 0;
  int frames = -1;
  bool noPlot = false;
  bool quiet = false;
  bool featureLevel = false;
  OdometrySettings settings;
};

void printMetrics(const nlohmann::json& m) {
  auto number = [&](const char* key, const char* format) {
    if (!m.contains(key) || m[key].is_null()) return;
    std::printf("  %-24s ", key);
    std::printf(format, m[key].get<double>());
    std::printf("\n");
  };
  std::printf("  %-24s %d of %d\n", "frames tracked", m["frames_tracked"].get<int>(), m["frames"].get<int>());
  if (m["frames_predicted"].get<int>() > 0)
    std::printf("  %-24s %d (constant velocity through a tracking loss)\n", "frames predicted",
                m["frames_predicted"].get<int>());
  if (m["frames_bad"].get<int>() > 0)
    std::printf("  %-24s %d (skipped: unusable images; frames.csv says why)\n", "bad frames",
                m["frames_bad"].get<int>());
  number("segments", "%.0f");
  number("fps", "%.1f (the odometry alone: front end and back end)");
  number("distance_m", "%.1f m");
  number("ate_rmse_m", "%.3f m (SE3-aligned)");
  number("ate_sim3_rmse_m", "%.3f m (Sim3-aligned)");
  number("drift_percent", "%.3f %% (KITTI segments)");
  number("scale_error_percent", "%+.3f %% (Sim3 alignment)");
  number("path_length_error_percent", "%+.3f %% (path length)");
  number("final_position_error_m", "%.3f m (start-aligned)");
}

void printHeader(const std::string& name, int frames, const Rig& rig, const RunOptions& options) {
  const OdometryOptions& odometry = options.odometry;
  std::printf("lrsvo run %s: %d frames, %d cameras, window %d keyframes, S %s%s, detector %s\n", name.c_str(), frames,
              static_cast<int>(rig.cameras.size()), odometry.windowSize, extrinsicModeName(odometry.extrinsicMode),
              odometry.extrinsicMode == ExtrinsicMode::kBounded ? (" by " + odometry.constraintMethod).c_str() : "",
              options.frontEnd.tracker.detector.name.c_str());
  std::fflush(stdout);
}

void runCommand(const RunCommandOptions& o) {
  RunOptions options = o.settings.runOptions();
  options.firstFrame = o.first;
  options.maxFrames = o.frames;
  options.outDir =
      o.out.empty() ? std::filesystem::path("lrsvo_runs") / folderName(o.source) : std::filesystem::path(o.out);
  if (!o.quiet) options.progress = &std::cerr;
  const StopOnSignal stop;
  options.stop = &stop.requested();
  const auto [run, truth] =
      runSource(o.source, options, o.featureLevel,
                [&](const std::string& name, int frames, const Rig& rig) { printHeader(name, frames, rig, options); });
  const RunReport report = writeRunReport(options.outDir, run, truth, !o.noPlot);
  printMetrics(report.metrics);
  if (!report.warning.empty()) std::printf("  note: %s\n", report.warning.c_str());
  std::printf("  output in %s/ (trajectory.tum, extrinsics.csv, frames.csv, metrics.json", options.outDir.c_str());
  for (const auto& plot : report.plots) std::printf(", %s", plot.filename().c_str());
  std::printf(")\n");
  if (run.stopped) std::printf("  stopped early by a signal: the outputs cover the frames done\n");
  std::fflush(stdout);
  stop.throwIfRequested();
}

void addRunCommand(CLI::App& app) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* command = app.add_subcommand("run", "Run the long-range stereo odometry on a stereo sequence");
  command
      ->add_option("source", options->source,
                   "sim:demo | sim:paper | sim:stress | sim:FILE.yaml (a synthetic flight rendered on the fly), or a "
                   "data set folder in the EuRoC (DIR/mav0) or KITTI odometry (DIR/image_0, calib.txt) layout; "
                   "euroc:DIR or kitti:DIR forces the layout")
      ->required();
  command->add_option("--out", options->out, "Output folder (default lrsvo_runs/<source>)");
  command->add_option("--first", options->first, "Start at this frame of the source (0 = its first)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--frames", options->frames, "Stop after this many frames (default: all)");
  command->add_flag("--no-plot", options->noPlot, "Write tables and metrics.json only, no PNG");
  command->add_flag("--quiet", options->quiet, "No progress line");
  command->add_flag("--feature-level", options->featureLevel,
                    "For sim: sources: simulate the flight's feature observations (0.5 px noise, ~300 points in "
                    "view) instead of rendering and tracking images; the odometry back end alone, in minutes for "
                    "the 9600-frame paper flight");
  options->settings.addOptions(*command);
  command->footer(
      "Writes trajectory.tum (TUM format, base camera), extrinsics.csv (S per frame, and the truth when known), "
      "frames.csv (per frame: features, inliers, window error, time per stage), rig.json, and with ground truth "
      "metrics.json (frames, frames_tracked, distance_m, ate_rmse_m, drift_percent, scale_error_percent, fps, ...) "
      "and plots: trajectory_top.png, position_error.png, orientation_error.png, extrinsics.png. fps is the "
      "odometry's own rate, without reading or rendering frames. Frames before the first initialisation, and after "
      "a tracking loss until the next, have no pose: the trajectory skips them and frames.csv marks them (status "
      "initialising, or bad_frame with the reason in note). Above the progress line, a line of its own tells each "
      "skipped frame, each segment's start (how it started and, after a loss, why tracking was lost) and each "
      "relocalisation. Ctrl-C or SIGTERM stops after the current frame and "
      "writes every output for the frames done (exit status 130 or 143); a second Ctrl-C quits at once. Each "
      "frame's lines are written whole as it is estimated, so even a killed run leaves no broken line.");
  command->callback([options] { runCommand(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("run", addRunCommand);

}  // namespace lrsvo::cli
