// `lrsvo graph`: optimises a pose graph in g2o's text format (or a generated
// one) with any registered solver and writes the result in the same format.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "apps/command.h"
#include "lrsvo/edges/g2o_file.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/stopwatch.h"
#include "lrsvo/sim/pose_graph_generator.h"

namespace lrsvo::cli {
namespace {

struct GraphCommandOptions {
  std::string file;
  std::string generate;
  PoseGraphOptions generator;
  std::string write;
  bool noSolve = false;
  std::string solver = "lm_cholmod";
  int threads = 1;
  int maxIterations = SolverOptions{}.maxIterations;
  std::string json;
  std::string out;
  bool geodesicAcceleration = false;
  bool verbose = false;
};

Graph loadOrGenerate(GraphCommandOptions& o) {
  const Stopwatch start;
  if (o.generate.empty()) {
    Graph graph = loadG2oFile(o.file);
    std::printf("Pose graph %s: %zu vertices, %zu edges (read in %.3f s)\n", o.file.c_str(), graph.vertices().size(),
                graph.edges().size(), start.seconds());
    return graph;
  }
  o.generator.shape = poseGraphShapeFromName(o.generate);
  Graph graph = generatePoseGraph(o.generator);
  std::printf("Generated %s pose graph (%dD, seed %llu): %zu vertices, %zu edges (%.3f s)\n", o.generate.c_str(),
              o.generator.dimension, static_cast<unsigned long long>(o.generator.seed), graph.vertices().size(),
              graph.edges().size(), start.seconds());
  if (!o.write.empty()) {
    saveG2oFile(graph, o.write);
    std::printf("Wrote the generated graph to %s\n", o.write.c_str());
  }
  return graph;
}

// The gauge: the file's FIX lines, or else the first vertex held fixed.
void fixGauge(Graph& graph) {
  int fixed = 0;
  for (const auto& vertex : graph.vertices()) fixed += vertex->fixed() ? 1 : 0;
  if (fixed > 0) {
    std::printf("Gauge: %d vertices fixed by FIX lines\n", fixed);
    return;
  }
  graph.vertices().front()->setFixed(true);
  std::printf("Gauge: the first vertex (id %d) held fixed\n", graph.vertices().front()->id());
}

void run(GraphCommandOptions& o) {
  if (o.generate.empty() && o.file.empty())
    throw Error("graph: give a g2o FILE, or --generate sphere|grid (see lrsvo graph --help)");
  SolverOptions solverOptions = SolverOptions::fromName(o.solver);
  solverOptions.threads = o.threads;
  solverOptions.maxIterations = o.maxIterations;
  solverOptions.verbose = o.verbose;
  solverOptions.lm.geodesicAcceleration = o.geodesicAcceleration;
  Optimizer optimizer(solverOptions);

  Graph graph = loadOrGenerate(o);
  if (graph.empty()) throw Error("graph: " + o.file + " has no vertices");
  if (!o.noSolve) {
    fixGauge(graph);
    const SolverSummary summary = optimizer.optimize(graph);
    std::cout << summary.fullReport();
    std::printf("graph: initial cost %.9e, final cost %.9e, %d iterations, %.3f s, termination %s\n",
                summary.initialCost, summary.finalCost, summary.iterationCount(), summary.totalSeconds,
                terminationName(summary.termination));
    std::cout.flush();
    if (!o.json.empty()) {
      std::ofstream json(o.json);
      json << summary.toJson() << '\n';
      if (!json) throw Error("graph: cannot write '" + o.json + "'");
    }
  }
  if (!o.out.empty()) {
    saveG2oFile(graph, o.out);
    std::printf("Wrote the %s graph to %s\n", o.noSolve ? "unsolved" : "optimised", o.out.c_str());
  }
}

void addGraphCommand(CLI::App& app) {
  auto options = std::make_shared<GraphCommandOptions>();
  CLI::App* command = app.add_subcommand("graph", "Optimise a pose graph in g2o's format (or a generated one)");
  command->footer(
      "Reads VERTEX_SE2, EDGE_SE2, VERTEX_SE3:QUAT, EDGE_SE3:QUAT and FIX lines (docs/pose_graphs.md). Without FIX\n"
      "lines the first vertex is held fixed (the gauge). Costs are 1/2 sum r^T Omega r (g2o's chi2 / 2).\n"
      "Examples:\n"
      "  lrsvo graph pose3example.txt --out optimised.g2o\n"
      "  lrsvo graph intel.g2o --solver gn_cholmod --max-iterations 20 --json summary.json\n"
      "  lrsvo graph --generate sphere --poses 2500 --seed 1 --write sphere.g2o --no-solve\n"
      "  lrsvo graph --generate grid --dimension 2 --poses 10000 --seed 3 --out grid_optimised.g2o\n"
      "`lrsvo solvers` lists the solver names.");

  CLI::Option* file = command->add_option("file", options->file, "g2o file to read");
  command->add_option("--solver", options->solver, "Solver <algorithm>_<linear solver>, see `lrsvo solvers`")
      ->capture_default_str();
  command->add_option("--threads", options->threads, "Threads for linearisation and the factorisation")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--max-iterations", options->maxIterations, "Iteration cap")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--out", options->out, "Write the optimised graph as a g2o file (17 significant digits)");
  command->add_option("--json", options->json, "Write the solver summary as JSON to this file");
  command->add_flag("--no-solve", options->noSolve, "Only read (or generate) and write the graph, do not optimise");
  command->add_flag("--geodesic-acceleration", options->geodesicAcceleration,
                    "Correct each Levenberg-Marquardt step by the residuals' curvature along it");
  command->add_flag("--verbose", options->verbose, "Print one line per iteration (stderr)");

  CLI::Option_group* generator = command->add_option_group("Generator", "Generate a graph instead of reading FILE");
  CLI::Option* generate = generator
                              ->add_option("--generate", options->generate,
                                           "Shape: sphere (SE3 rings with loop closures between rings) or grid "
                                           "(a walk on a lattice, closing loops where it returns)")
                              ->check(CLI::IsMember({"sphere", "grid"}))
                              ->excludes(file);
  const auto needsGenerate = [&](CLI::Option* option) { option->needs(generate)->capture_default_str(); };
  needsGenerate(
      generator->add_option("--poses", options->generator.poses, "Number of poses")->check(CLI::Range(2, 100'000'000)));
  needsGenerate(generator->add_option("--dimension", options->generator.dimension, "The grid's: 2 (SE2) or 3 (SE3)")
                    ->check(CLI::IsMember({2, 3})));
  needsGenerate(generator->add_option("--seed", options->generator.seed, "Random seed"));
  needsGenerate(generator
                    ->add_option("--translation-noise", options->generator.translationSigma,
                                 "Sigma of the measurements' translation noise per axis")
                    ->check(CLI::PositiveNumber));
  needsGenerate(generator
                    ->add_option("--rotation-noise", options->generator.rotationSigma,
                                 "Sigma of the measurements' rotation noise per angle, radians")
                    ->check(CLI::PositiveNumber));
  generator->add_option("--write", options->write, "Write the generated graph (before solving) as a g2o file")
      ->needs(generate);

  command->callback([options] { run(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("graph", addGraphCommand);

}  // namespace lrsvo::cli
