// `lrsvo render SCENARIO --out DIR [--first I] [--frames N]`: renders a synthetic flight
// (sim/scenario.h: demo, paper or a YAML file) to images in the EuRoC layout,
// with the ground truth beside them, so that any stereo VO can run on it.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/command.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/graph/stopwatch.h"
#include "lrsvo/sim/euroc_writer.h"
#include "lrsvo/sim/sim_frame_source.h"

namespace lrsvo::cli {
namespace {

struct RenderCommandOptions {
  std::string scenario;
  std::string out;
  int first = 0;
  int frames = -1;
  int threads = 0;
};

void runRender(const RenderCommandOptions& o) {
  SimScenario scenario = loadScenario(o.scenario);
  if (o.threads > 0) scenario.render.threads = o.threads;
  const SimFrameSource source(scenario);
  const int frames = framesInRun(source.frameCount(), o.first, o.frames);
  EurocWriter writer(o.out, source.rig(), scenario.flight.frameRate_hz / scenario.flight.frameStep);
  const FlightTruth& truth = source.truth();
  const Stopwatch start;
  double lastReport = -1.0;
  for (int i = 0; i < frames; ++i) {
    const int index = o.first + i;
    writer.write(source.render(index), truth.cameraFromWorld[index].inverse(), truth.extrinsics[index]);
    const double elapsed = start.seconds();
    if (elapsed - lastReport >= 1.0 || i + 1 == frames) {
      const double fps = (i + 1) / elapsed;
      std::fprintf(stderr, "\rrender %s: frame %d/%d, %.2f frames/s, ETA %.0f s   ", source.name().c_str(), i + 1,
                   frames, fps, (frames - i - 1) / fps);
      lastReport = elapsed;
    }
  }
  std::fprintf(stderr, "\n");
  std::printf("wrote %d stereo frames of %s to %s (EuRoC layout, ground truth in groundtruth_cam0_tum.txt)\n", frames,
              source.name().c_str(), o.out.c_str());
}

void add(CLI::App& app) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command =
      app.add_subcommand("render", "Render a synthetic flight (demo, paper or a YAML scenario) to EuRoC-layout images");
  command->add_option("scenario", options->scenario, "demo, paper or a scenario YAML file (docs/simulator.md)")
      ->required();
  command->add_option("--out", options->out, "output directory")->required();
  command->add_option("--first", options->first, "start at this frame of the flight (0 = its first)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--frames", options->frames, "render only N frames (default: to the end of the flight)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--threads", options->threads, "rendering threads (default: the scenario's render.threads)")
      ->check(CLI::NonNegativeNumber);
  command->callback([options] { runRender(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("render", add);

}  // namespace lrsvo::cli
