// `lrsvo bench run`: the odometry's own speed on 1280x960 stereo images, per
// stage, and its memory as a run grows (it must stay flat). Frames are
// rendered before they reach the odometry; rendering is not timed. With
// --feature-level a sim: flight's observations go straight to the odometry
// (no images): the back end's speed and memory over thousands of frames in
// minutes rather than hours of rendering.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "apps/bench/bench_common.h"
#include "apps/command.h"
#include "apps/run_setup.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/sim/sim_frame_source.h"

namespace lrsvo::cli {
namespace {

struct BenchRunOptions {
  std::string source = "sim:paper";
  std::vector<int> checkpoints = {1000, 5000};
  bool featureLevel = false;
  OdometrySettings settings;
};

// Resident memory of this process now, in MiB (Linux /proc).
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// The most resident memory this process has held so far, in MiB (VmHWM in /proc/self/status; 0 if absent).
double peakResidentMiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.starts_with("VmHWM:")) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0.0;
}

// `render`: a sim: source's renderer time by stage, or null for other sources.
void printStages(const RunTotals& t, const RenderTimes* render) {
  const double n = std::max(1, t.frames);
  const double odometry_ms = 1e3 * t.odometrySeconds() / n;
  auto row = [&](const char* stage, double total_ms) {
    std::printf("  %-22s %8.2f ms/frame %6.1f %%\n", stage, total_ms / n, 100.0 * total_ms / n / odometry_ms);
  };
  row("detect", t.frontEnd.detect_ms);
  row("track (KLT)", t.frontEnd.track_ms);
  row("stereo match", t.frontEnd.stereo_ms);
  row("undistort", t.frontEnd.undistort_ms);
  row("initialise", t.backEnd.initialize_ms);
  row("pose (P3P + MLESAC)", t.backEnd.pose_ms);
  row("triangulate", t.backEnd.triangulate_ms);
  row("window adjustment", t.backEnd.bundle_ms);
  std::printf("  %-22s %8.2f ms/frame  = %.1f fps (rendering: %.1f ms/frame, not counted)\n", "odometry", odometry_ms,
              t.fps(), 1e3 * t.sourceSeconds / n);
  if (render == nullptr) return;
  std::printf(
      "  rendering, by stage: view %.2f, texture caches %.2f, trace and shade %.2f, sensor %.2f ms/frame "
      "(%.2f images a frame); rendering / odometry %.2f\n",
      1e3 * render->view_s / n, 1e3 * render->texture_s / n, 1e3 * render->shade_s / n, 1e3 * render->sensor_s / n,
      render->images / n, t.sourceSeconds / t.odometrySeconds());
}

void benchRun(BenchRunOptions o) {
  std::sort(o.checkpoints.begin(), o.checkpoints.end());
  if (o.checkpoints.empty() || o.checkpoints.front() < 1) throw Error("bench run: checkpoints must be positive");
  std::unique_ptr<FrameSource> source;
  std::optional<FeatureLevelFlight> flight;
  if (o.featureLevel)
    flight = simulateFeatureLevel(o.source);
  else
    source = openSource(o.source);
  const std::string name = flight ? flight->name : source->name();
  const int frameCount = flight ? static_cast<int>(flight->frames.size()) : source->frameCount();
  const int last = o.checkpoints.back();
  if (frameCount >= 0 && frameCount < last)
    throw Error("bench run: " + name + " has " + std::to_string(frameCount) +
                " frames, fewer than the last checkpoint " + std::to_string(last));
  const RunOptions options = o.settings.runOptions();
  const Rig& rig = flight ? flight->rig : source->rig();
  OdometryPipeline pipeline =
      flight ? OdometryPipeline(rig, std::vector<LensDistortion>(rig.cameras.size()), flight->truth, options)
             : OdometryPipeline(*source, options);
  const Camera& camera = rig.cameras[0];
  std::printf("lrsvo bench run: %s, %dx%d, window %d, S %s; memory and speed at frames", name.c_str(), camera.width,
              camera.height, options.odometry.windowSize, extrinsicModeName(options.odometry.extrinsicMode));
  for (int c : o.checkpoints) std::printf(" %d", c);
  std::printf("\n");
  std::printf("  resident memory before the first frame: %.1f MiB\n", residentMiB());
  std::size_t next = 0;
  double sourceSeconds = 0.0;
  for (int frame = 1; frame <= last; ++frame) {
    if (flight) {
      pipeline.process(flight->frames[static_cast<std::size_t>(frame - 1)]);
    } else {
      Stopwatch render;
      std::optional<StereoFrame> images = source->next();
      sourceSeconds += render.seconds();
      if (!images) break;
      pipeline.process(*images);
    }
    if (frame % 100 == 0) std::fprintf(stderr, "\rframe %d/%d  %.1f fps   ", frame, last, pipeline.totals().fps());
    if (next < o.checkpoints.size() && frame == o.checkpoints[next]) {
      RunTotals totals = pipeline.totals();
      totals.sourceSeconds += sourceSeconds;
      std::fprintf(stderr, "\n");
      std::printf("\nafter %d frames: resident memory %.1f MiB (peak so far %.1f MiB), %d tracked, %d keyframes\n",
                  frame, residentMiB(), peakResidentMiB(), totals.tracked, totals.keyframes);
      const auto* sim = dynamic_cast<const SimFrameSource*>(source.get());
      printStages(totals, sim ? &sim->renderTimes() : nullptr);
      ++next;
    }
  }
  std::printf("\nThe paper's implementation: 741 ms per frame (1.35 Hz); the cameras: 30 Hz.\n");
}

void addBenchRun(CLI::App& app) {
  auto options = std::make_shared<BenchRunOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "run", "Frames per second of the odometry alone on 1280x960 stereo, time per stage, memory over a long run");
  command->add_option("--source", options->source, "Any `lrsvo run` source with enough frames")->capture_default_str();
  command
      ->add_option("--checkpoints", options->checkpoints,
                   "Frame counts at which to report speed and memory (e.g. 1000,5000)")
      ->delimiter(',')
      ->capture_default_str();
  command->add_flag("--feature-level", options->featureLevel,
                    "A sim: flight's observations straight into the odometry, no images (the back end alone)");
  options->settings.addOptions(*command);
  command->callback([options] { benchRun(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench run", addBenchRun);

}  // namespace lrsvo::cli
