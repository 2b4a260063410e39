#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrsvo/graph/solver_summary.h"
#include "lrsvo/graph/stopwatch.h"

namespace CLI {
class App;
}

namespace lrsvo::bench {

// The `bench` subcommand of the lrsvo program, created by whichever
// benchmark registers first; each benchmark adds itself under it.
CLI::App& benchSubcommand(CLI::App& app);

// What one solve reports, whichever library ran it. Phase times follow each
// library's own accounting (see docs/benchmarks.md).
struct SolveResult {
  int iterations = 0;
  double initialCost = 0.0;  // 1/2 sum |r|^2 at the start
  double finalCost = 0.0;
  double totalSeconds = 0.0;  // wall time of the solve call alone
  double cpuSeconds = 0.0;    // process CPU time of the same call, all threads
  std::string termination;
  double setupSeconds = 0.0;             // ordering, symbolic analysis
  double linearizeSeconds = 0.0;         // residuals and Jacobians (ours: also the H and g blocks)
  double linearSolveSeconds = 0.0;       // Schur elimination, factorisation, back-substitution
  std::optional<double> schurSeconds;    // part of linearSolveSeconds, when the library reports it
  double costSeconds = 0.0;              // cost of trial steps
  std::optional<double> solveMegabytes;  // memory the solve call added at its peak (SolveMemory)
  std::string ordering;                  // ours: the direct solver's fill-reducing ordering (SolverSummary)
  std::optional<double> factorizationFlops;

  // Time of one iteration of the minimiser loop: (total - setup) / iterations.
  double secondsPerIteration() const { return (totalSeconds - setupSeconds) / (iterations > 0 ? iterations : 1); }
};

// The memory one solve call adds to the process: its resident size at the
// peak during the call above its resident size just before (Linux: the peak is
// reset through /proc/self/clear_refs). The model's own memory, built before
// the call (our graph, Ceres' Problem), is not counted. Nothing where /proc
// cannot tell.
class SolveMemory {
 public:
  SolveMemory();                                 // resets the peak; construct just before the solve call
  std::optional<double> addedMegabytes() const;  // read just after it

 private:
  std::optional<double> residentBefore_;
};

// Our SolverSummary in the common form, with the times the stopwatch measured around the solve.
SolveResult resultFromSummary(const SolverSummary& summary, const Stopwatch& stopwatch);

// Runs `solve` `repeat` times (each run must start from the same state) and
// returns the run with the median total time (the lower median for even
// counts), so that every figure in the result comes from one real run.
// `progress` is called before each run with its 1-based number.
SolveResult medianRun(int repeat, const std::function<SolveResult()>& solve,
                      const std::function<void(int run)>& progress = {});

// One row of a comparison: a solve of one problem by one solver. Reference
// rows are the other library's (Ceres); the ratio fields are ours / reference
// and stay empty on reference rows.
struct BenchRow {
  std::string problem;
  nlohmann::ordered_json problemFields;  // sizes etc., written between "problem" and "solver"
  std::string solver;
  std::string family;  // ours and references of the same family are compared head to head
  bool reference = false;
  std::string jacobians;  // "analytic", "autodiff", ...
  int threads = 1;
  SolveResult result;
  std::optional<double> ratioTime;         // against the reference of the same family and threads
  std::optional<double> ratioTimeFastest;  // against the fastest reference at the same threads
  std::optional<double> ratioCost;         // final cost against the same reference as ratioTime
};

// Fills the ratio fields of the non-reference rows among rows[first, end),
// which must all be solves of one problem.
void computeRatios(std::vector<BenchRow>& rows, std::size_t first);

// The rows as a JSON list of objects (problem, <problemFields>, solver,
// threads, iterations, time_per_iteration_s, total_time_s, initial_cost,
// final_cost, ratio_time, ratio_cost, ... ; absent ratios are null).
nlohmann::ordered_json rowsToJson(const std::vector<BenchRow>& rows);
// Writes rowsToJson(rows) to path; throws lrsvo::Error when it cannot.
void writeJson(const std::vector<BenchRow>& rows, const std::string& path);
// Writes any JSON value (e.g. rowsToJson(rows) with a bench's own keys added) to path.
void writeJsonValue(const nlohmann::ordered_json& value, const std::string& path);

// A plain-text table: a header and rows of cells, columns padded to fit,
// text left-aligned and numbers right-aligned.
class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header) : header_(std::move(header)) {}
  void addRow(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  void addSeparator() { rows_.emplace_back(); }
  void print(std::ostream& out) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;  // an empty row is a separator line
};

// printf-style formatting into a std::string.
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
// A ratio as "0.873", or "-" when absent.
std::string formatRatio(const std::optional<double>& ratio);

}  // namespace lrsvo::bench
