// `lrsvo bench nist`: the NIST StRD regression suite solved by lrsvo and by
// Ceres in one process, same models, same starts, same stopping rules.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/bench/bench_common.h"
#include "apps/bench/ceres_nist.h"
#include "apps/command.h"
#include "lrsvo/eval/nist_regression.h"
#include "lrsvo/graph/error.h"

namespace lrsvo::cli {
namespace {

struct BenchNistOptions {
  std::string directory;
  std::string json;
};

// Solved count, digit sum and time of one library over the suite.
struct Tally {
  int solved = 0;
  double digits = 0.0;
  double seconds = 0.0;
  void add(double minDigits, double solveSeconds) {
    solved += minDigits >= 4.0;
    digits += minDigits;
    seconds += solveSeconds;
  }
};

void run(const BenchNistOptions& o) {
  const NistSolveOptions options;
  const std::vector<std::string> files = nistProblemFiles(o.directory);
  std::printf(
      "NIST StRD: lrsvo (%s, automatic differentiation) against Ceres (LM, DENSE_QR, Jets),\n"
      "every tolerance %.3g, at most %d iterations; digits = smallest log relative error over the parameters\n",
      options.solver.name().c_str(), options.solver.functionTolerance, options.solver.maxIterations);
  std::printf("%-9s %5s %12s %12s %12s %12s\n", "problem", "start", "lrsvo digits", "Ceres digits", "lrsvo iter",
              "Ceres iter");
  Tally ours, ceres;
  nlohmann::json rows = nlohmann::json::array();
  for (const std::string& file : files) {
    const NistProblem problem = readNistProblem(file);
    for (int start : {1, 2}) {
      const NistSolve solve = solveNist(problem, start, options);
      const bench::CeresNistSolve reference = bench::solveNistWithCeres(problem, start, options.solver);
      const double referenceDigits = correctDigits(reference.estimate, problem.certified).minCoeff();
      ours.add(solve.minDigits(), solve.summary.totalSeconds);
      ceres.add(referenceDigits, reference.result.totalSeconds);
      std::printf("%-9s %5d %12.2f %12.2f %12d %12d\n", problem.name.c_str(), start, solve.minDigits(), referenceDigits,
                  solve.summary.iterationCount(), reference.result.iterations);
      std::fflush(stdout);
      rows.push_back({{"problem", problem.name},
                      {"start", start},
                      {"lrsvo_digits", solve.minDigits()},
                      {"ceres_digits", referenceDigits},
                      {"lrsvo_iterations", solve.summary.iterationCount()},
                      {"ceres_iterations", reference.result.iterations},
                      {"lrsvo_seconds", solve.summary.totalSeconds},
                      {"ceres_seconds", reference.result.totalSeconds}});
    }
  }
  const int solves = static_cast<int>(rows.size());
  std::printf("lrsvo: solved %d of %d, mean digits %.2f, %.3f s in all\n", ours.solved, solves, ours.digits / solves,
              ours.seconds);
  std::printf("Ceres: solved %d of %d, mean digits %.2f, %.3f s in all\n", ceres.solved, solves, ceres.digits / solves,
              ceres.seconds);
  std::printf("Time, lrsvo / Ceres: %.2f\n", ours.seconds / ceres.seconds);
  if (!o.json.empty()) {
    std::ofstream out(o.json);
    out << nlohmann::json{{"lrsvo_solved", ours.solved},
                          {"ceres_solved", ceres.solved},
                          {"solves", solves},
                          {"lrsvo_mean_digits", ours.digits / solves},
                          {"ceres_mean_digits", ceres.digits / solves},
                          {"runs", rows}}
               .dump(2)
        << '\n';
    if (!out) throw Error("cannot write '" + o.json + "'");
  }
}

void addBenchNist(CLI::App& app) {
  auto options = std::make_shared<BenchNistOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "nist", "The NIST StRD regression suite, lrsvo against Ceres (correct digits, iterations, time)");
  command->footer("Example:\n  lrsvo bench nist ../shared/data/nist --json bench_nist.json");
  command->add_option("directory", options->directory, "Folder of NIST StRD .dat files")->required();
  command->add_option("--json", options->json, "Write every solve and the totals as JSON to this file");
  command->callback([options] { run(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench nist", addBenchNist);

}  // namespace lrsvo::cli
