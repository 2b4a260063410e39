// `lrsvo bal`: bundle adjustment of a BAL file, or of a generated BAL-format
// problem, with any registered solver.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/command.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo::cli {
namespace {

struct BalCommandOptions {
  std::string file;
  bool generate = false;
  BalGeneratorOptions generator;
  std::string write;
  std::string solver = "lm_schur_cholmod";
  int threads = 1;
  int maxIterations = SolverOptions{}.maxIterations;
  std::string kernel;
  double kernelDelta = 1.0;
  std::string damping = "multiplicative";
  std::string json;
  std::string out;
  bool verbose = false;
  int solves = 1;
};

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text << '\n';
  out.close();
  if (!out) throw Error("cannot write '" + path + "'");
}

BalProblem loadProblem(const BalCommandOptions& o) {
  const Stopwatch start;
  if (!o.generate) {
    BalProblem problem = readBal(o.file);
    std::printf("BAL problem %s: %zu cameras, %zu points, %zu observations (read in %.3f s)\n", o.file.c_str(),
                problem.cameras.size(), problem.points.size(), problem.observations.size(), start.seconds());
    return problem;
  }
  BalProblem problem = generateBalProblem(o.generator);
  std::printf(
      "Generated BAL problem (seed %llu, pixel noise %.3g px): %zu cameras, %zu points, %zu observations "
      "(%.3f s)\n",
      static_cast<unsigned long long>(o.generator.seed), o.generator.pixelNoise, problem.cameras.size(),
      problem.points.size(), problem.observations.size(), start.seconds());
  if (!o.write.empty()) {
    writeBal(problem, o.write);
    std::printf("Wrote the generated problem to %s\n", o.write.c_str());
  }
  return problem;
}

void run(const BalCommandOptions& o) {
  if (!o.generate && o.file.empty()) throw Error("bal: give a BAL FILE, or --generate (see lrsvo bal --help)");
  SolverOptions solverOptions = SolverOptions::fromName(o.solver);
  solverOptions.threads = o.threads;
  solverOptions.maxIterations = o.maxIterations;
  solverOptions.lm.damping = dampingFromName(o.damping);
  solverOptions.verbose = o.verbose;
  Optimizer optimizer(solverOptions);

  BalProblem problem = loadProblem(o);
  const double startRms = rmsReprojectionError(problem);
  const Stopwatch buildStart;
  Graph graph = makeBalGraph(problem, o.kernel, o.kernelDelta);
  std::printf("Graph built in %.3f s", buildStart.seconds());
  if (!o.kernel.empty()) std::printf(", robust kernel %s, delta %g px", o.kernel.c_str(), o.kernelDelta);
  std::printf("\n");

  // Later solves start where the first did, on the structure the optimizer kept.
  const std::vector<double> start = o.solves > 1 ? graph.estimates() : std::vector<double>{};
  SolverSummary summary;
  for (int k = 1; k <= o.solves; ++k) {
    if (k > 1) graph.setEstimates(start);
    summary = optimizer.optimize(graph);
    if (o.solves > 1)
      std::printf("Solve %d of %d: setup %.4f s%s, total %.4f s\n", k, o.solves, summary.setupSeconds,
                  summary.structureReused ? " (structure reused)" : "", summary.totalSeconds);
  }
  updateFromGraph(problem, graph);
  std::cout << summary.fullReport();
  std::printf("RMS reprojection error per image coordinate: %.4f px at the start, %.4f px at the end\n", startRms,
              rmsReprojectionError(problem));
  std::cout.flush();

  if (!o.json.empty()) writeText(o.json, summary.toJson());
  if (!o.out.empty()) {
    writeBal(problem, o.out);
    std::printf("Wrote the optimised problem to %s\n", o.out.c_str());
  }
}

std::vector<std::string> kernelNames() {
  std::vector<std::string> names;
  for (const auto& [name, entry] : Registry<RobustKernel>::instance().entries()) names.push_back(name);
  return names;
}

void addBalCommand(CLI::App& app) {
  auto options = std::make_shared<BalCommandOptions>();
  CLI::App* command = app.add_subcommand("bal", "Bundle adjustment of a BAL file (or a generated BAL problem)");
  command->footer(
      "Examples:\n"
      "  lrsvo bal problem-49-7776-pre.txt --solver lm_schur_cholmod --threads 2 --json summary.json\n"
      "  lrsvo bal problem.txt --kernel Huber --kernel-delta 2 --out optimised.txt\n"
      "  lrsvo bal --generate --cameras 50 --points 10000 --seed 1 --write generated.txt\n"
      "Public BAL files are .bz2 archives: bunzip2 them first. `lrsvo solvers` lists the solver names.");

  CLI::Option* file = command->add_option("file", options->file, "BAL file to read (uncompressed text)");
  command->add_option("--solver", options->solver, "Solver <algorithm>_<linear solver>, see `lrsvo solvers`")
      ->capture_default_str();
  command
      ->add_option("--threads", options->threads,
                   "Threads for linearisation, the Schur complement and the factorisation")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--max-iterations", options->maxIterations, "Iteration cap")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  CLI::Option* kernel = command->add_option("--kernel", options->kernel, "Robust kernel on the reprojection error")
                            ->check(CLI::IsMember(kernelNames()));
  command->add_option("--kernel-delta", options->kernelDelta, "Kernel inlier threshold, pixels")
      ->check(CLI::PositiveNumber)
      ->needs(kernel)
      ->capture_default_str();
  command->add_option("--damping", options->damping, "Levenberg-Marquardt damping: diag(H)(1+lambda) or diag(H)+lambda")
      ->check(CLI::IsMember({"multiplicative", "additive"}))
      ->capture_default_str();
  command->add_option("--json", options->json, "Write the solver summary as JSON to this file");
  command->add_option("--out", options->out, "Write the optimised problem as a BAL file");
  command->add_flag("--verbose", options->verbose, "Print one line per iteration (stderr)");
  command
      ->add_option("--solves", options->solves,
                   "Solve this many times, each from the same start, on one optimizer: the solves after the first "
                   "reuse its block structure and symbolic analysis (each solve's setup is printed; the report is "
                   "the last one's)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  CLI::Option_group* generator = command->add_option_group("Generator", "Generate a problem instead of reading FILE");
  CLI::Option* generate =
      generator->add_flag("--generate", options->generate, "Generate a seeded BAL problem")->excludes(file);
  const auto needsGenerate = [&](CLI::Option* option) { option->needs(generate)->capture_default_str(); };
  needsGenerate(generator->add_option("--cameras", options->generator.cameras, "Number of cameras")
                    ->check(CLI::Range(2, 1'000'000)));
  needsGenerate(generator->add_option("--points", options->generator.points, "Number of points")
                    ->check(CLI::Range(1, 100'000'000)));
  needsGenerate(generator->add_option("--observations-per-point", options->generator.observationsPerPoint,
                                      "Mean number of cameras seeing a point (at least 2)"));
  needsGenerate(generator->add_option("--seed", options->generator.seed, "Random seed"));
  needsGenerate(
      generator->add_option("--pixel-noise", options->generator.pixelNoise, "Sigma of the observation noise, pixels"));
  needsGenerate(generator->add_option("--rotation-noise", options->generator.rotationNoise,
                                      "Sigma of the start's rotation error, radians"));
  needsGenerate(generator->add_option("--translation-noise", options->generator.translationNoise,
                                      "Sigma of the start's camera translation error, metres"));
  needsGenerate(generator->add_option("--point-noise", options->generator.pointNoise,
                                      "Sigma of the start's point position error, metres"));
  generator->add_option("--write", options->write, "Write the generated problem (before solving) as a BAL file")
      ->needs(generate);

  command->callback([options] { run(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bal", addBalCommand);

}  // namespace lrsvo::cli
