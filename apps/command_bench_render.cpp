// `lrsvo bench render`: where the renderer's time goes on a synthetic flight,
// streamed as `lrsvo run` streams it (the base image of every frame, the
// secondary images of one frame in K, as the odometry asks for them on its
// keyframes), so that its time per frame reads against `lrsvo bench run`'s
// odometry time.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "apps/bench/bench_common.h"
#include "apps/command.h"
#include "lrsvo/frontend/odometry/odometry_run.h"
#include "lrsvo/sim/sim_frame_source.h"

namespace lrsvo::cli {
namespace {

struct BenchRenderOptions {
  std::string scenario = "demo";
  int first = 0;
  int frames = 150;
  int secondaryEvery = 3;
  int warmUp = 10;
};

RenderTimes since(const RenderTimes& now, const RenderTimes& before) {
  return {now.images - before.images, now.view_s - before.view_s, now.texture_s - before.texture_s,
          now.shade_s - before.shade_s, now.sensor_s - before.sensor_s};
}

void benchRender(const BenchRenderOptions& o) {
  SimFrameSource source(loadScenario(o.scenario));
  const int frames = framesInRun(source.frameCount(), o.first + o.warmUp, o.frames);
  const Camera& camera = source.rig().cameras[0];
  std::printf(
      "lrsvo bench render: %s, %dx%d, %d threads, frames %d-%d after %d warm-up frames (the first fills the texture's "
      "caches for its whole view), secondary images on one frame in %d\n",
      source.name().c_str(), camera.width, camera.height, source.scenario().render.threads, o.first + o.warmUp,
      o.first + o.warmUp + frames - 1, o.warmUp, o.secondaryEvery);
  source.skip(o.first);
  auto stream = [&](int i) {
    std::optional<StereoFrame> frame = source.next();
    if (i % o.secondaryEvery == 0)
      for (int k = 1; k < frame->cameraCount(); ++k) frame->image(k);
  };
  for (int i = 0; i < o.warmUp; ++i) stream(i);
  const RenderTimes before = source.renderTimes();
  const Stopwatch stopwatch;
  for (int i = 0; i < frames; ++i) {
    stream(o.warmUp + i);
    if ((i + 1) % 10 == 0 || i + 1 == frames)
      std::fprintf(stderr, "\rframe %d/%d, %.1f frames/s   ", i + 1, frames, (i + 1) / stopwatch.seconds());
  }
  std::fprintf(stderr, "\n");
  const RenderTimes t = since(source.renderTimes(), before);
  const double total = t.total_s();
  auto row = [&](const char* stage, double seconds) {
    std::printf("  %-34s %8.2f ms/image %8.2f ms/frame %6.1f %%\n", stage, 1e3 * seconds / t.images,
                1e3 * seconds / frames, 100.0 * seconds / total);
  };
  std::printf("%d images (%.2f a frame), wall %.1f s, CPU %.1f s\n", t.images, static_cast<double>(t.images) / frames,
              stopwatch.seconds(), stopwatch.cpuSeconds());
  row("view (ground grid, obstacles)", t.view_s);
  row("texture caches (new texel tiles)", t.texture_s);
  row("trace and shade the pixels", t.shade_s);
  row("sensor (gain, blur, noise, 8 bit)", t.sensor_s);
  row("rendering", total);
  std::printf("Compare the last ms/frame with the odometry's in `lrsvo bench run --source sim:%s`.\n",
              o.scenario.c_str());
}

void addBenchRender(CLI::App& app) {
  auto options = std::make_shared<BenchRenderOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "render", "Where the renderer's time goes per image and per streamed frame of a synthetic flight");
  command->add_option("--scenario", options->scenario, "demo, paper or a scenario YAML file (docs/simulator.md)")
      ->capture_default_str();
  command->add_option("--first", options->first, "start at this frame of the flight")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--frames", options->frames, "frames to render")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--warm-up", options->warmUp, "frames rendered first and not counted")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      ->add_option("--secondary-every", options->secondaryEvery,
                   "render the secondary cameras on one frame in K (a streamed run does on its keyframes)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->callback([options] { benchRender(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench render", addBenchRender);

}  // namespace lrsvo::cli
