// `lrsvo bench bal`: this project's Schur solvers against Ceres' SPARSE_SCHUR,
// DENSE_SCHUR and ITERATIVE_SCHUR on generated BAL problems, same start and
// stopping rules, at each thread count, in one process.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/types.h>

#include "apps/bench/bench_common.h"
#include "apps/bench/ceres_bal.h"
#include "apps/command.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"

namespace lrsvo::cli {
namespace {

using bench::BenchRow;
using bench::format;
using bench::SolveResult;

constexpr double kInitialCostTolerance = 1e-9;  // relative; more means the two models differ
constexpr double kFinalCostTolerance = 1e-3;    // ours may end at most 0.1 % above Ceres

struct BenchBalOptions {
  std::vector<std::string> sizes{"small:20x5000", "medium:50x20000", "large:150x60000"};
  std::uint64_t seed = 1;
  int observationsPerPoint = BalGeneratorOptions{}.observationsPerPoint;
  double startNoise = 1.0;
  std::vector<int> threads{1, 2};
  std::vector<std::string> solvers{"lm_schur_cholmod", "lm_schur_dense", "lm_schur_pcg",
                                   "SPARSE_SCHUR",     "DENSE_SCHUR",    "ITERATIVE_SCHUR"};
  int maxIterations = 50;
  int repeat = 1;
  std::string json;
};

struct ProblemSize {
  std::string name;
  int cameras = 0;
  int points = 0;
};

// "[name:]CAMERASxPOINTS", e.g. "small:20x5000" or "20x5000".
ProblemSize parseSize(const std::string& text) {
  const auto fail = [&] { return Error("bench bal: --sizes entry '" + text + "' is not [name:]CAMERASxPOINTS"); };
  ProblemSize size;
  const auto colon = text.find(':');
  const std::string dims = colon == std::string::npos ? text : text.substr(colon + 1);
  const auto x = dims.find('x');
  if (x == std::string::npos) throw fail();
  try {
    std::size_t used = 0;
    size.cameras = std::stoi(dims.substr(0, x), &used);
    if (used != x) throw fail();
    size.points = std::stoi(dims.substr(x + 1), &used);
    if (used != dims.size() - x - 1) throw fail();
  } catch (const std::logic_error&) {
    throw fail();
  }
  if (size.cameras < 2 || size.points < 1) throw Error("bench bal: '" + text + "' needs >= 2 cameras and >= 1 point");
  size.name = colon == std::string::npos ? dims : text.substr(0, colon);
  return size;
}

// One solver of the comparison. Ours and Ceres of the same family (sparse or
// dense reduced system, or iterative) are compared head to head.
struct Contender {
  const char* key;    // its name in --solvers
  const char* label;  // as printed
  const char* family;
  bool ceres;
  ceres::LinearSolverType ceresSolver;  // used by the Ceres ones
};

const Contender kContenders[] = {
    {"lm_schur_cholmod", "lm_schur_cholmod", "sparse", false, ceres::SPARSE_SCHUR},
    {"lm_schur_dense", "lm_schur_dense", "dense", false, ceres::DENSE_SCHUR},
    {"lm_schur_pcg", "lm_schur_pcg", "iterative", false, ceres::ITERATIVE_SCHUR},
    {"lm_schur_power_series", "lm_schur_power_series", "iterative", false, ceres::ITERATIVE_SCHUR},
    {"SPARSE_SCHUR", "ceres SPARSE_SCHUR", "sparse", true, ceres::SPARSE_SCHUR},
    {"DENSE_SCHUR", "ceres DENSE_SCHUR", "dense", true, ceres::DENSE_SCHUR},
    {"ITERATIVE_SCHUR", "ceres ITERATIVE_SCHUR", "iterative", true, ceres::ITERATIVE_SCHUR},
};

std::vector<const Contender*> selectContenders(const std::vector<std::string>& keys) {
  std::vector<const Contender*> selected;
  for (const Contender& contender : kContenders)
    if (std::find(keys.begin(), keys.end(), contender.key) != keys.end()) selected.push_back(&contender);
  for (const std::string& key : keys)
    if (std::none_of(std::begin(kContenders), std::end(kContenders), [&](const Contender& c) { return key == c.key; }))
      throw Error("bench bal: unknown solver '" + key +
                  "' in --solvers (known: lm_schur_cholmod, lm_schur_dense, lm_schur_pcg, lm_schur_power_series, "
                  "SPARSE_SCHUR, DENSE_SCHUR, ITERATIVE_SCHUR)");
  return selected;
}

SolveResult solveOnce(const Contender& contender, const BalProblem& start, const SolverOptions& stopping) {
  if (contender.ceres) {
    BalProblem problem = start;
    return bench::solveBalWithCeres(problem, stopping, contender.ceresSolver);
  }
  const SolverOptions named = SolverOptions::fromName(contender.key);
  SolverOptions options = stopping;
  options.algorithm = named.algorithm;
  options.linearSolver = named.linearSolver;
  Graph graph = makeBalGraph(start);
  const bench::SolveMemory memory;
  const Stopwatch stopwatch;
  const SolverSummary summary = Optimizer(options).optimize(graph);
  SolveResult result = bench::resultFromSummary(summary, stopwatch);
  result.solveMegabytes = memory.addedMegabytes();
  return result;
}

void printBalResults(const std::vector<BenchRow>& rows) {
  bench::TextTable table({"problem", "solver", "threads", "iterations", "s/iteration", "total s", "cpu s", "solve MB",
                          "initial cost", "final cost", "stop", "time/Ceres", "time/fastest", "cost/Ceres"});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& row = rows[i];
    const SolveResult& r = row.result;
    if (i > 0 && (row.problem != rows[i - 1].problem || row.threads != rows[i - 1].threads)) table.addSeparator();
    table.addRow({row.problem, row.solver, std::to_string(row.threads), std::to_string(r.iterations),
                  format("%.4f", r.secondsPerIteration()), format("%.3f", r.totalSeconds), format("%.3f", r.cpuSeconds),
                  r.solveMegabytes ? format("%.1f", *r.solveMegabytes) : "-", format("%.8e", r.initialCost),
                  format("%.8e", r.finalCost), r.termination, bench::formatRatio(row.ratioTime),
                  bench::formatRatio(row.ratioTimeFastest), bench::formatRatio(row.ratioCost)});
  }
  table.print(std::cout);
}

void printPhases(const std::vector<BenchRow>& rows) {
  std::cout << "\nwhere the time goes (seconds per solve; ours: linearize = residuals, Jacobians and H/g blocks; "
               "Ceres: linearize = residuals and Jacobians, its Schur elimination is in linear solve)\n";
  bench::TextTable table({"problem", "solver", "threads", "setup", "linearize", "linear solve", "of which Schur",
                          "trial costs", "other", "total"});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& row = rows[i];
    const SolveResult& r = row.result;
    if (i > 0 && (row.problem != rows[i - 1].problem || row.threads != rows[i - 1].threads)) table.addSeparator();
    const double other = r.totalSeconds - r.setupSeconds - r.linearizeSeconds - r.linearSolveSeconds - r.costSeconds;
    table.addRow({row.problem, row.solver, std::to_string(row.threads), format("%.3f", r.setupSeconds),
                  format("%.3f", r.linearizeSeconds), format("%.3f", r.linearSolveSeconds),
                  r.schurSeconds ? format("%.3f", *r.schurSeconds) : "-", format("%.3f", r.costSeconds),
                  format("%.3f", other), format("%.3f", r.totalSeconds)});
  }
  table.print(std::cout);
}

// The checks the comparison rests on: identical models (initial costs) and
// final costs within 0.1 % of Ceres.
void printChecks(const std::vector<BenchRow>& rows) {
  std::cout << '\n';
  std::string lastProblem;
  for (const BenchRow& first : rows) {
    if (first.problem == lastProblem) continue;
    lastProblem = first.problem;
    const double reference = std::max(std::abs(first.result.initialCost), std::numeric_limits<double>::min());
    double largest = 0.0;
    int solves = 0;
    for (const BenchRow& row : rows) {
      if (row.problem != first.problem) continue;
      largest = std::max(largest, std::abs(row.result.initialCost - first.result.initialCost) / reference);
      ++solves;
    }
    if (largest <= kInitialCostTolerance)
      std::cout << format("check %s: initial costs of all %d solves agree (largest relative difference %.1e <= %.0e)\n",
                          first.problem.c_str(), solves, largest, kInitialCostTolerance);
    else
      std::cout << format("WARNING %s: initial costs differ by %.1e relative (> %.0e): the two models do not match\n",
                          first.problem.c_str(), largest, kInitialCostTolerance);
  }

  int ours = 0, worse = 0, fasterSame = 0, fasterFastest = 0;
  for (const BenchRow& row : rows) {
    if (!row.ratioCost) continue;
    ++ours;
    if (row.ratioTime && *row.ratioTime < 1.0) ++fasterSame;
    if (row.ratioTimeFastest && *row.ratioTimeFastest < 1.0) ++fasterFastest;
    if (*row.ratioCost <= 1.0 + kFinalCostTolerance) continue;
    ++worse;
    std::cout << format("WORSE %s %s %d thread(s): final cost %.8e is %.3f %% above Ceres'\n", row.problem.c_str(),
                        row.solver.c_str(), row.threads, row.result.finalCost, 100.0 * (*row.ratioCost - 1.0));
  }
  if (ours == 0) return;  // no pair of ours and Ceres to compare
  if (worse == 0)
    std::cout << format("check: every one of our %d solves ends within %.1f %% of Ceres' final cost (or below)\n", ours,
                        100.0 * kFinalCostTolerance);
  std::cout << format(
      "ours faster than the same-family Ceres in %d of %d solves, faster than the fastest Ceres in %d\n", fasterSame,
      ours, fasterFastest);
}

// What is compared and how, so that a pasted table carries its method.
void printPreamble(const SolverOptions& stopping, int repeat) {
  std::cout << "lrsvo bench bal: ours (analytic Jacobians, LM, multiplicative damping diag(H) (1 + lambda))\n"
            << "  against " << bench::ceresConfiguration() << "\n"
            << format(
                   "stopping (both): function %.0e, gradient %.0e, parameter %.0e, at most %d iterations, "
                   "start lambda 1e-4\n",
                   stopping.functionTolerance, stopping.gradientTolerance, stopping.parameterTolerance,
                   stopping.maxIterations)
            << format(
                   "times: wall time of the solve call (ours Optimizer::optimize, Ceres ceres::Solve), median of "
                   "%d run(s); cpu s = process CPU time of that call, all threads\n",
                   repeat)
            << "iterations = steps computed (Ceres: its summary's iterations plus the last step, which it computes "
               "and discards when a tolerance stops it); s/iteration = (total - setup) / iterations\n"
            << "solve MB = resident memory the solve call added at its peak (the model built before it, our graph "
               "or Ceres' Problem, not counted)\n"
            << "note: Ceres scales Jacobian columns (jacobi_scaling) and damps diag(J^T J) of the scaled system; "
               "ours damps diag(H) (1 + lambda) unscaled: close analogues, not identical steps\n\n";
}

void runBenchBal(const BenchBalOptions& options) {
  std::vector<ProblemSize> sizes;
  for (const auto& text : options.sizes) sizes.push_back(parseSize(text));
  for (int threads : options.threads)
    if (threads < 1) throw Error("bench bal: --threads values must be at least 1");
  if (options.maxIterations < 1) throw Error("bench bal: --max-iterations must be at least 1");
  if (options.repeat < 1) throw Error("bench bal: --repeat must be at least 1");
  if (options.observationsPerPoint < 2) throw Error("bench bal: --observations-per-point must be at least 2");
  if (!(options.startNoise >= 0.0 && std::isfinite(options.startNoise)))
    throw Error("bench bal: --start-noise must be finite and not negative");
  const std::vector<const Contender*> contenders = selectContenders(options.solvers);
  if (!options.json.empty()) bench::writeJson({}, options.json);  // fail now, not after the solves

  SolverOptions stopping;  // Ceres' default tolerances
  stopping.lm.damping = Damping::kMultiplicative;
  stopping.maxIterations = options.maxIterations;

  printPreamble(stopping, options.repeat);

  std::vector<BenchRow> rows;
  for (const ProblemSize& size : sizes) {
    BalGeneratorOptions generator;
    generator.cameras = size.cameras;
    generator.points = size.points;
    generator.observationsPerPoint = options.observationsPerPoint;
    generator.seed = options.seed;
    generator.rotationNoise *= options.startNoise;
    generator.translationNoise *= options.startNoise;
    generator.pointNoise *= options.startNoise;
    std::cerr << "[bench bal] generating " << size.name << " (" << size.cameras << " cameras, " << size.points
              << " points, seed " << options.seed << ")" << std::endl;
    const BalProblem start = generateBalProblem(generator);
    std::cout << format("problem %s: %d cameras, %d points, %zu observations (seed %llu, start noise x%g)\n",
                        size.name.c_str(), size.cameras, size.points, start.observations.size(),
                        static_cast<unsigned long long>(options.seed), options.startNoise);

    const std::size_t first = rows.size();
    for (int threads : options.threads) {
      stopping.threads = threads;
      for (const Contender* contender : contenders) {
        BenchRow row;
        row.problem = size.name;
        row.problemFields["cameras"] = size.cameras;
        row.problemFields["points"] = size.points;
        row.problemFields["observations"] = start.observations.size();
        row.solver = contender->label;
        row.family = contender->family;
        row.reference = contender->ceres;
        row.jacobians = contender->ceres ? "autodiff" : "analytic";
        row.threads = threads;
        row.result = bench::medianRun(
            options.repeat, [&] { return solveOnce(*contender, start, stopping); },
            [&](int run) {
              std::cerr << "[bench bal] " << size.name << ": " << contender->label << ", " << threads
                        << " thread(s), run " << run << "/" << options.repeat << std::endl;
            });
        std::cerr << format("[bench bal]   %d iterations, %.3f s, final cost %.8e\n", row.result.iterations,
                            row.result.totalSeconds, row.result.finalCost);
        rows.push_back(std::move(row));
      }
    }
    bench::computeRatios(rows, first);
  }

  std::cout << '\n';
  printBalResults(rows);
  printPhases(rows);
  printChecks(rows);
  if (!options.json.empty()) {
    bench::writeJson(rows, options.json);
    std::cout << "wrote " << options.json << '\n';
  }
}

void addBenchBal(CLI::App& app) {
  auto options = std::make_shared<BenchBalOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "bal", "Our Schur solvers against Ceres SPARSE_SCHUR / DENSE_SCHUR / ITERATIVE_SCHUR on generated BAL problems");
  command->add_option("--sizes", options->sizes, "Problems as [name:]CAMERASxPOINTS")->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the problem generator")->capture_default_str();
  command->add_option("--observations-per-point", options->observationsPerPoint, "Mean observations per point")
      ->capture_default_str();
  command
      ->add_option("--start-noise", options->startNoise,
                   "Scale of the generator's start perturbations (rotation, translation, point)")
      ->capture_default_str();
  command->add_option("--solvers", options->solvers, "Which solvers to run")->capture_default_str();
  command->add_option("--threads", options->threads, "Thread counts to run every solver at")->capture_default_str();
  command->add_option("--max-iterations", options->maxIterations, "Iteration cap for both libraries")
      ->capture_default_str();
  command->add_option("--repeat", options->repeat, "Runs per solve; the median time is reported")
      ->capture_default_str();
  command->add_option("--json", options->json, "Also write the results as a JSON list to FILE");
  command->callback([options] { runBenchBal(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench bal", addBenchBal);

}  // namespace lrsvo::cli
