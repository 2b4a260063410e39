// `lrsvo demo`: the project's default job. A synthetic long-range flight is
// rendered (sim:demo: ~100 m above farmland, 0.7 m baseline, a rig that
// flexes in flight) and the odometry runs on its images three ways: the
// extrinsic bounded (the paper's method), free (unconstrained) and rigid.
// One table compares them with the ground truth.
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

struct DemoOptions {
  std::string source = "sim:demo";
  std::string out = "lrsvo_demo";
  int first = 0;
  int frames = -1;
  bool noPlot = false;
  bool quiet = false;
  bool featureLevel = false;
  OdometrySettings settings;
};

struct Variant {
  const char* name;
  const char* what;
  ExtrinsicMode mode;
};

constexpr Variant kVariants[] = {
    {"constrained", "S bounded (the paper's method)", ExtrinsicMode::kBounded},
    {"unconstrained", "S free", ExtrinsicMode::kFree},
    {"rigid", "S held at calibration", ExtrinsicMode::kRigid},
};

std::string cell(const nlohmann::json& metrics, const char* key, const char* format) {
  if (!metrics.contains(key) || metrics[key].is_null()) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, metrics[key].get<double>());
  return text;
}

void runDemo(const DemoOptions& o) {
  std::vector<RunOptions> variants;
  for (const Variant& variant : kVariants) {
    RunOptions options = o.settings.runOptions();
    options.odometry.extrinsicMode = variant.mode;
    options.firstFrame = o.first;
    options.maxFrames = o.frames;
    options.outDir = std::filesystem::path(o.out) / variant.name;
    variants.push_back(options);
  }
  if (!o.quiet)
    for (RunOptions& variant : variants) variant.progress = &std::cerr;
  const StopOnSignal stop;
  for (RunOptions& variant : variants) variant.stop = &stop.requested();
  std::vector<RunResult> runs;
  GroundTruth truth;
  auto header = [&](const std::string& name, int count, const Rig& rig) {
    count = framesInRun(count, o.first, o.frames);
    std::printf("lrsvo demo: %s, %d frames of %dx%d stereo (baseline %.2f m), the odometry three ways on the same %s\n",
                name.c_str(), count, rig.cameras[0].width, rig.cameras[0].height, rig.extrinsics[0].head<3>().norm(),
                o.featureLevel ? "observations" : "images");
    std::fflush(stdout);
  };
  if (o.featureLevel) {
    FeatureLevelFlight flight = simulateFeatureLevel(o.source);
    header(flight.name, static_cast<int>(flight.frames.size()), flight.rig);
    runs = runOdometry(flight.rig, flight.frames, flight.truth, variants);
    truth = std::move(flight.truth);
  } else {
    std::unique_ptr<FrameSource> source = openSource(o.source);
    header(source->name(), source->frameCount(), source->rig());
    for (std::size_t i = 1; i < variants.size(); ++i) variants[i].progress = nullptr;  // one shared stream
    runs = runOdometry(*source, variants);
    truth = source->groundTruth();
  }

  std::printf("\n%-14s %-32s %9s %9s %10s %10s %11s %12s %7s\n", "variant", "stereo extrinsic S", "tracked", "distance",
              "ATE (m)", "drift (%)", "scale (%)", "final (m)", "fps");
  std::vector<std::string> notes;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunReport report = writeRunReport(variants[i].outDir, runs[i], truth, !o.noPlot);
    const nlohmann::json& m = report.metrics;
    std::printf("%-14s %-32s %9s %9s %10s %10s %11s %12s %7s\n", kVariants[i].name, kVariants[i].what,
                (std::to_string(runs[i].totals.tracked) + "/" + std::to_string(runs[i].totals.frames)).c_str(),
                cell(m, "distance_m", "%.0f m").c_str(), cell(m, "ate_rmse_m", "%.2f").c_str(),
                cell(m, "drift_percent", "%.2f").c_str(), cell(m, "scale_error_percent", "%+.2f").c_str(),
                cell(m, "final_position_error_m", "%.2f").c_str(), cell(m, "fps", "%.1f").c_str());
    if (!report.warning.empty()) notes.push_back(std::string(kVariants[i].name) + ": " + report.warning);
    for (const auto& plot : report.plots) notes.push_back("plot: " + plot.string());
  }
  std::printf(
      "\ndrift: KITTI-style mean translational error over 100-800 m segments (shorter runs: the segments that fit); "
      "scale: size against the truth (Sim3 alignment); final: last position, start-aligned; fps: the odometry "
      "alone.\n");
  for (const std::string& note : notes) std::printf("  %s\n", note.c_str());
  std::printf("Outputs in %s/{constrained,unconstrained,rigid}/\n", o.out.c_str());
  if (stop.requested()) std::printf("Stopped early by a signal: the outputs cover the frames done\n");
  std::fflush(stdout);
  stop.throwIfRequested();
}

void addDemoCommand(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* command = app.add_subcommand(
      "demo", "Render a synthetic long-range flight and run the odometry constrained, unconstrained and rigid on it");
  command->add_option("--source", options->source, "The flight (any `lrsvo run` source)")->capture_default_str();
  command->add_option("--out", options->out, "Output folder: one subfolder per variant")->capture_default_str();
  command->add_option("--first", options->first, "Start at this frame of the flight (0 = its first)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--frames", options->frames, "Stop after this many frames (default: the whole flight)");
  command->add_flag("--no-plot", options->noPlot, "Write tables and metrics.json only, no PNG");
  command->add_flag("--quiet", options->quiet, "No progress line");
  command->add_flag("--feature-level", options->featureLevel,
                    "Simulate the flight's feature observations instead of rendering images (the back end alone; "
                    "minutes for --source sim:paper)");
  options->settings.addOptions(*command);
  command->footer(
      "Every frame is rendered once and fed to the three odometries. Each variant's folder holds what `lrsvo run` "
      "writes (trajectory.tum, extrinsics.csv, frames.csv, metrics.json, plots). --constraint picks the method of "
      "the constrained variant; --rigid is ignored here.");
  command->callback([options] { runDemo(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("demo", addDemoCommand);

}  // namespace lrsvo::cli
