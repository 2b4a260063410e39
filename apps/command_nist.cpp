// `lrsvo nist`: the NIST StRD nonlinear regression suite, every problem from
// both starts, with correct digits per solve.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "lrsvo/eval/nist_regression.h"
#include "lrsvo/graph/error.h"

namespace lrsvo::cli {
namespace {

struct NistCommandOptions {
  std::string directory;
  std::string solver = nistSolverOptions().name();
  std::string jacobians = "autodiff";
  int maxIterations = nistSolverOptions().maxIterations;
  std::string json;
  bool geodesicAcceleration = false;
  bool verbose = false;
};

NistSolveOptions solveOptions(const NistCommandOptions& o) {
  NistSolveOptions options;
  options.solver.setName(o.solver);
  options.solver.maxIterations = o.maxIterations;
  options.solver.verbose = o.verbose;
  options.solver.lm.geodesicAcceleration = o.geodesicAcceleration;
  if (o.jacobians != "autodiff") {
    options.jacobians = RegressionJacobians::kNumeric;
    options.numeric.method = o.jacobians == "forward"   ? NumericDifference::kForward
                             : o.jacobians == "ridders" ? NumericDifference::kRidders
                                                        : NumericDifference::kCentral;
  }
  return options;
}

void run(const NistCommandOptions& o) {
  const NistSolveOptions options = solveOptions(o);
  const std::vector<std::string> files = nistProblemFiles(o.directory);
  std::printf("NIST StRD nonlinear regression: %zu problems in %s, solver %s%s, %s Jacobians\n", files.size(),
              o.directory.c_str(), options.solver.name().c_str(),
              options.solver.lm.geodesicAcceleration ? " with geodesic acceleration" : "", o.jacobians.c_str());
  std::printf("%-9s %5s %7s %6s %10s %14s %14s  %s\n", "problem", "start", "digits", "solved", "iterations", "RSS",
              "certified RSS", "termination");
  nlohmann::json rows = nlohmann::json::array();
  int solved = 0, solves = 0;
  double digitSum = 0.0;
  for (const std::string& file : files) {
    const NistProblem problem = readNistProblem(file);
    for (int start : {1, 2}) {
      const NistSolve solve = solveNist(problem, start, options);
      ++solves;
      solved += solve.solved();
      digitSum += solve.minDigits();
      std::printf("%-9s %5d %7.2f %6s %10d %14.8e %14.8e  %s\n", problem.name.c_str(), start, solve.minDigits(),
                  solve.solved() ? "yes" : "NO", solve.summary.iterationCount(), solve.residualSumOfSquares,
                  problem.certifiedResidualSumOfSquares, terminationName(solve.summary.termination));
      std::fflush(stdout);
      rows.push_back({{"problem", problem.name},
                      {"start", start},
                      {"digits", solve.minDigits()},
                      {"estimate", std::vector<double>(solve.estimate.begin(), solve.estimate.end())},
                      {"certified", std::vector<double>(problem.certified.begin(), problem.certified.end())},
                      {"solved", solve.solved()},
                      {"iterations", solve.summary.iterationCount()},
                      {"rss", solve.residualSumOfSquares},
                      {"certified_rss", problem.certifiedResidualSumOfSquares},
                      {"termination", terminationName(solve.summary.termination)},
                      {"seconds", solve.summary.totalSeconds}});
    }
  }
  const double meanDigits = solves > 0 ? digitSum / solves : 0.0;
  std::printf("Solved %d of %d (every parameter to >= 4 digits); mean correct digits %.2f\n", solved, solves,
              meanDigits);
  if (!o.json.empty()) {
    std::ofstream out(o.json);
    out << nlohmann::json{{"solver", options.solver.name()},
                          {"jacobians", o.jacobians},
                          {"geodesic_acceleration", options.solver.lm.geodesicAcceleration},
                          {"solved", solved},
                          {"solves", solves},
                          {"mean_digits", meanDigits},
                          {"runs", rows}}
               .dump(2)
        << '\n';
    if (!out) throw Error("cannot write '" + o.json + "'");
  }
}

void addNistCommand(CLI::App& app) {
  auto options = std::make_shared<NistCommandOptions>();
  CLI::App* command =
      app.add_subcommand("nist", "Solve every NIST StRD nonlinear regression problem (*.dat in DIR) from both starts");
  command->footer(
      "Digits are the log relative error -log10(|b - c| / |c|) against the certified values c, the\n"
      "smallest over a problem's parameters, capped at 11 (the certified values' own precision);\n"
      "a solve counts as solved at 4 digits or more. Examples:\n"
      "  lrsvo nist ../shared/data/nist\n"
      "  lrsvo nist ../shared/data/nist --jacobians central --json nist.json\n"
      "  lrsvo nist ../shared/data/nist --geodesic-acceleration");
  command->add_option("directory", options->directory, "Folder of NIST StRD .dat files")->required();
  command->add_option("--solver", options->solver, "Solver <algorithm>_<linear solver>, see `lrsvo solvers`")
      ->capture_default_str();
  command
      ->add_option("--jacobians", options->jacobians,
                   "autodiff (dual numbers), or numeric differences: central, forward, ridders")
      ->check(CLI::IsMember({"autodiff", "central", "forward", "ridders"}))
      ->capture_default_str();
  command->add_option("--max-iterations", options->maxIterations, "Iteration cap per solve")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_flag("--geodesic-acceleration", options->geodesicAcceleration,
                    "Correct each Levenberg-Marquardt step by the residuals' curvature along it");
  command->add_option("--json", options->json, "Write every solve and the totals as JSON to this file");
  command->add_flag("--verbose", options->verbose, "Print one line per iteration (stderr)");
  command->callback([options] { run(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("nist", addNistCommand);

}  // namespace lrsvo::cli
