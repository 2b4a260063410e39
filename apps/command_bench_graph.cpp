// `lrsvo bench graph`: our sparse solver against Ceres' SPARSE_NORMAL_CHOLESKY
// on generated pose graphs, same residuals, start, gauge and stopping rules,
// in one process. It prints figures; it never fails on time.
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/bench/bench_common.h"
#include "apps/bench/ceres_pose_graph.h"
#include "apps/command.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/sim/pose_graph_generator.h"

namespace lrsvo::cli {
namespace {

using bench::BenchRow;
using bench::format;
using bench::SolveResult;

struct BenchGraphOptions {
  std::vector<std::string> shapes{"sphere", "grid2d"};
  std::vector<int> poses{2500, 10000};
  std::uint64_t seed = 1;
  std::string solver = "lm_cholmod";
  int threads = 1;
  int maxIterations = 50;
  int repeat = 1;
  std::string json;
};

// "sphere", "grid2d" or "grid3d" as generator options.
PoseGraphOptions generatorOptions(const std::string& shape, int poses, std::uint64_t seed) {
  PoseGraphOptions options;
  options.shape = shape == "sphere" ? PoseGraphShape::kSphere : PoseGraphShape::kGrid;
  options.dimension = shape == "grid2d" ? 2 : 3;
  options.poses = poses;
  options.seed = seed;
  return options;
}

// A fresh copy of the start, its first vertex fixed (the gauge): every solve
// begins from the same generated graph.
Graph startGraph(const PoseGraphOptions& options) {
  Graph graph = generatePoseGraph(options);
  graph.vertices().front()->setFixed(true);
  return graph;
}

SolveResult solveOurs(const PoseGraphOptions& problem, const SolverOptions& options) {
  Graph graph = startGraph(problem);
  const Stopwatch stopwatch;
  const SolverSummary summary = Optimizer(options).optimize(graph);
  return bench::resultFromSummary(summary, stopwatch);
}

SolveResult solveCeres(const PoseGraphOptions& problem, const SolverOptions& stopping) {
  Graph graph = startGraph(problem);
  return bench::solvePoseGraphWithCeres(graph, stopping);
}

void printGraphResults(const std::vector<BenchRow>& rows) {
  bench::TextTable table({"problem", "solver", "iterations", "total s", "cpu s", "initial cost", "final cost", "stop",
                          "time/Ceres", "cost/Ceres"});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& row = rows[i];
    const SolveResult& r = row.result;
    if (i > 0 && row.problem != rows[i - 1].problem) table.addSeparator();
    table.addRow({row.problem, row.solver, std::to_string(r.iterations), format("%.3f", r.totalSeconds),
                  format("%.3f", r.cpuSeconds), format("%.10e", r.initialCost), format("%.10e", r.finalCost),
                  r.termination, bench::formatRatio(row.ratioTime), bench::formatRatio(row.ratioCost)});
  }
  table.print(std::cout);
}

void printPreamble(const BenchGraphOptions& options, const SolverOptions& stopping) {
  std::cout << "lrsvo bench graph: ours (" << options.solver << ", analytic Jacobians)\n"
            << "  against " << bench::ceresPoseGraphConfiguration() << "\n"
            << format(
                   "stopping (both): function %.0e, gradient %.0e, parameter %.0e, at most %d iterations, start "
                   "lambda 1e-4; first vertex fixed; %d thread(s)\n",
                   stopping.functionTolerance, stopping.gradientTolerance, stopping.parameterTolerance,
                   stopping.maxIterations, stopping.threads)
            << format(
                   "times: wall time of the solve call, median of %d run(s); cpu s = process CPU time of that call; "
                   "costs 1/2 sum r^T Omega r\n\n",
                   options.repeat);
}

void runBenchGraph(const BenchGraphOptions& options) {
  for (int poses : options.poses)
    if (poses < 2) throw Error("bench graph: --poses values must be at least 2");
  if (options.maxIterations < 1) throw Error("bench graph: --max-iterations must be at least 1");
  if (options.repeat < 1) throw Error("bench graph: --repeat must be at least 1");
  if (!options.json.empty()) bench::writeJson({}, options.json);  // fail now, not after the solves

  SolverOptions stopping = SolverOptions::fromName(options.solver);
  stopping.maxIterations = options.maxIterations;
  stopping.threads = options.threads;
  printPreamble(options, stopping);

  std::vector<BenchRow> rows;
  for (const std::string& shape : options.shapes) {
    for (int poses : options.poses) {
      const PoseGraphOptions problem = generatorOptions(shape, poses, options.seed);
      const std::string name = shape + ":" + std::to_string(poses);
      const Graph sample = generatePoseGraph(problem);
      std::cout << format("problem %s: %zu poses, %zu edges (seed %llu)\n", name.c_str(), sample.vertices().size(),
                          sample.edges().size(), static_cast<unsigned long long>(options.seed));
      const std::size_t first = rows.size();
      for (const bool ceres : {false, true}) {
        BenchRow row;
        row.problem = name;
        row.problemFields["poses"] = sample.vertices().size();
        row.problemFields["edges"] = sample.edges().size();
        row.solver = ceres ? "ceres SPARSE_NORMAL_CHOLESKY" : options.solver;
        row.family = "sparse";
        row.reference = ceres;
        row.jacobians = ceres ? "autodiff" : "analytic";
        row.threads = options.threads;
        row.result = bench::medianRun(
            options.repeat, [&] { return ceres ? solveCeres(problem, stopping) : solveOurs(problem, stopping); },
            [&](int run) {
              std::cerr << "[bench graph] " << name << ": " << row.solver << ", run " << run << "/" << options.repeat
                        << std::endl;
            });
        rows.push_back(std::move(row));
      }
      bench::computeRatios(rows, first);
    }
  }
  std::cout << '\n';
  printGraphResults(rows);
  if (!options.json.empty()) {
    bench::writeJson(rows, options.json);
    std::cout << "wrote " << options.json << '\n';
  }
}

void addBenchGraph(CLI::App& app) {
  auto options = std::make_shared<BenchGraphOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "graph", "Our sparse solver against Ceres SPARSE_NORMAL_CHOLESKY on generated pose graphs");
  command->footer(
      "Shapes: sphere (SE3 rings), grid2d (SE2 lattice walk), grid3d (SE3 lattice walk); see "
      "docs/pose_graphs.md.");
  command->add_option("--shapes", options->shapes, "Generated shapes")
      ->check(CLI::IsMember({"sphere", "grid2d", "grid3d"}))
      ->capture_default_str();
  command->add_option("--poses", options->poses, "Pose counts of the generated graphs")->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the generator")->capture_default_str();
  command->add_option("--solver", options->solver, "Our solver, see `lrsvo solvers`")->capture_default_str();
  command->add_option("--threads", options->threads, "Threads of both libraries")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--max-iterations", options->maxIterations, "Iteration cap for both libraries")
      ->capture_default_str();
  command->add_option("--repeat", options->repeat, "Runs per solve; the median time is reported")
      ->capture_default_str();
  command->add_option("--json", options->json, "Also write the results as a JSON list to FILE");
  command->callback([options] { runBenchGraph(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench graph", addBenchGraph);

}  // namespace lrsvo::cli
