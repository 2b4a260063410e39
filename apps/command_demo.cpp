// `lrsvo demo`: the project's default job (until the odometry exists): solve a
// generated bundle-adjustment problem and say whether the solve is sound.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "apps/command.h"
#include "edges/bal_problem.h"
#include "graph/error.h"
#include "graph/optimizer.h"

namespace lrsvo::cli {
namespace {

// A sound solve ends with residuals at the level of the pixel noise it was
// generated with; the allowance covers the problem's few degrees of freedom per observation.
constexpr double kMaxRmsOverNoise = 1.2;

struct DemoOptions {
  BalGeneratorOptions generator{.cameras = 50, .points = 10000, .seed = 1};
  int threads = 1;
};

void runDemo(const DemoOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  BalProblem problem = generateBalProblem(o.generator);
  std::printf(
      "Demo: bundle adjustment of a generated BAL problem (seed %llu): %zu cameras, %zu points, "
      "%zu observations, pixel noise %.3g px\n",
      static_cast<unsigned long long>(o.generator.seed), problem.cameras.size(), problem.points.size(),
      problem.observations.size(), o.generator.pixelNoise);
  const double startRms = rmsReprojectionError(problem);

  SolverOptions options = SolverOptions::fromName("lm_schur_cholmod");
  options.threads = o.threads;
  Graph graph = makeBalGraph(problem);
  const SolverSummary summary = Optimizer(options).optimize(graph);
  updateFromGraph(problem, graph);
  const double finalRms = rmsReprojectionError(problem);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << summary.fullReport();
  std::printf("RMS reprojection error per image coordinate: %.4f px at the start, %.4f px at the end\n", startRms,
              finalRms);
  const bool sound = summary.converged() && summary.finalCost < summary.initialCost &&
                     finalRms <= kMaxRmsOverNoise * o.generator.pixelNoise;
  std::printf("Verdict: %s: %s after %d iterations, cost %.4e -> %.4e, RMS %.3f px (noise %.3g px), %.2f s in all\n",
              sound ? "OK" : "FAILED", summary.converged() ? "converged" : "did not converge", summary.iterationCount(),
              summary.initialCost, summary.finalCost, finalRms, o.generator.pixelNoise, seconds);
  std::fflush(stdout);
  if (!sound)
    throw Error(std::string("demo: the solve is not sound (termination ") + terminationName(summary.termination) + ")");
}

void addDemoCommand(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* command = app.add_subcommand(
      "demo", "Solve a generated bundle-adjustment problem (50 cameras, 10000 points) with lm_schur_cholmod");
  command->footer(
      "Exits with status 1 when the solve does not converge to the noise level. "
      "For other sizes and solvers use `lrsvo bal --generate`.");
  command->add_option("--seed", options->generator.seed, "Random seed of the generated problem")->capture_default_str();
  command->add_option("--threads", options->threads, "Solver threads")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->callback([options] { runDemo(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("demo", addDemoCommand);

}  // namespace lrsvo::cli
