// `lrsvo bench window`: every constraint method of ours against Ceres
// (DENSE_SCHUR, SPARSE_SCHUR, bounds through SetParameterLower/UpperBound) on
// seeded sliding-window stereo problems like the VO's, and on the real KITTI
// problem "gtsam_vo_large", same start and stopping rules, in one process.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ceres/types.h>

#include "apps/bench/bench_common.h"
#include "apps/bench/ceres_stereo.h"
#include "apps/command.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/frontend/datasets/gtsam_stereo_vo.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/sim/window_problem.h"

namespace lrsvo::cli {
namespace {

using bench::BenchRow;
using bench::format;
using bench::SolveResult;

constexpr double kInitialCostTolerance = 1e-9;  // relative; more means the two models differ
constexpr double kFinalCostTolerance = 1e-3;    // ours may end at most 0.1 % above Ceres
constexpr double kGoalSpeedup = 3.0;            // the goal: at least 3x faster than Ceres' fastest
constexpr double kAtBound = 1e-9;               // on a bound: this close to it, relative to the half-width
const char* const kKittiProblem = "gtsam_vo_large";

struct BenchWindowOptions {
  std::vector<double> altitudes{30.0, 60.0, 90.0, 120.0};
  int count = 2;
  std::string active = "alternate";
  std::uint64_t seed = 1;
  int frames = 15;
  int points = 500;
  double pixelNoise = 1.0;
  std::vector<std::string> solvers;  // empty: all
  std::vector<std::string> linearSolvers{"schur_dense", "schur_cholmod"};
  int threads = 1;
  int maxIterations = 100;
  int repeat = 5;
  int kittiRepeat = 3;
  int nloptRepeat = 1;
  int nloptEvaluations = 1000;
  int nloptRounds = 3;
  std::optional<double> barrierMu;  // unset: the method's own default
  std::optional<int> barrierRounds;
  bool kitti = true;
  // Relative to the working directory: the repository's top, with the shared data beside it.
  std::string kittiDirectory = "../shared/data/gtsam_stereo_vo";
  bool kittiDirectoryGiven = false;
  std::string json;
};

bool isNlopt(const std::string& method) { return method.rfind("nlopt_", 0) == 0; }

// One solver of the comparison: a constraint method of ours with a linear
// solver (NLopt methods use none), or Ceres with one of its Schur solvers.
// Ceres without bounds is a reference for `none`: the same problem without
// the box, to tell the cost of Ceres' bound handling from its raw speed.
struct Contender {
  std::string label;
  std::string method;        // ours
  std::string linearSolver;  // ours, "" for NLopt
  bool ceres = false;
  ceres::LinearSolverType ceresSolver = ceres::DENSE_SCHUR;
  bool withBounds = true;  // Ceres: set the bounds

  bool ignoresBounds() const { return method == "none" || (ceres && !withBounds); }
  std::string family() const {
    if (ceres && !withBounds) return "ceres_no_bounds";
    if (ceres) return ceresSolver == ceres::DENSE_SCHUR ? "dense" : "sparse";
    if (linearSolver.empty()) return "nlopt";
    return linearSolver == "schur_dense" ? "dense" : "sparse";
  }
};

const std::pair<const char*, ceres::LinearSolverType> kCeresSolvers[] = {{"DENSE_SCHUR", ceres::DENSE_SCHUR},
                                                                         {"SPARSE_SCHUR", ceres::SPARSE_SCHUR}};
const char* const kCeresWithoutBounds = "DENSE_SCHUR_NO_BOUNDS";

// Every registered constraint method (LM ones first, NLopt last), each LM one
// with every linear solver, then Ceres; filtered by --solvers.
// A method's specification with the settings the bench's options give it.
std::string methodSpecification(const std::string& method, const BenchWindowOptions& o) {
  std::string settings;
  const auto add = [&](const std::string& setting) { settings += (settings.empty() ? ":" : ",") + setting; };
  if (method == "log_barrier") {
    if (o.barrierMu) add(format("mu=%.17g", *o.barrierMu));
    if (o.barrierRounds) add(format("rounds=%d", *o.barrierRounds));
  } else if (isNlopt(method)) {
    add(format("evaluations=%d", o.nloptEvaluations));
    add(format("rounds=%d", o.nloptRounds));
  }
  return method + settings;
}

// "name: setting=value ..." of the method as the bench runs it.
std::string describeMethod(const std::string& method, const BenchWindowOptions& o) {
  std::string text = method + ":";
  const std::unique_ptr<ConstraintMethod> made = makeConstraintMethod(methodSpecification(method, o));
  for (const MethodSetting& setting : made->ownSettings()) text += " " + setting.name + "=" + setting.valueText();
  return text;
}

std::vector<Contender> windowContenders(const BenchWindowOptions& options) {
  std::vector<std::string> methods;
  for (const auto& [name, entry] : Registry<ConstraintMethod>::instance().entries()) methods.push_back(name);
  std::stable_partition(methods.begin(), methods.end(), [](const std::string& m) { return !isNlopt(m); });

  std::vector<std::string> known = methods;
  for (const auto& [name, type] : kCeresSolvers) known.emplace_back(name);
  known.emplace_back(kCeresWithoutBounds);
  for (const std::string& key : options.solvers)
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw Error("bench window: unknown solver '" + key + "' in --solvers (known: " + list + ")");
    }
  const auto selected = [&](const std::string& key) {
    return options.solvers.empty() ||
           std::find(options.solvers.begin(), options.solvers.end(), key) != options.solvers.end();
  };

  std::vector<Contender> contenders;
  for (const std::string& method : methods) {
    if (!selected(method)) continue;
    if (isNlopt(method)) {
      contenders.push_back({method, method, "", false});
      continue;
    }
    for (const std::string& linearSolver : options.linearSolvers)
      contenders.push_back({method + " " + linearSolver, method, linearSolver, false});
  }
  for (const auto& [name, type] : kCeresSolvers)
    if (selected(name)) contenders.push_back({std::string("ceres ") + name, "", "", true, type});
  if (selected(kCeresWithoutBounds))
    contenders.push_back({"ceres DENSE_SCHUR no bounds", "", "", true, ceres::DENSE_SCHUR, false});
  return contenders;
}

// On KITTI there are no bounds, so every LM method is plain LM: ours once
// per linear solver (when any LM method is selected), and Ceres.
std::vector<Contender> kittiContenders(const std::vector<Contender>& window) {
  std::vector<Contender> contenders;
  for (const Contender& c : window) {
    if (c.ceres && c.withBounds) {
      contenders.push_back(c);
    } else if (!c.linearSolver.empty() && std::none_of(contenders.begin(), contenders.end(), [&](const Contender& o) {
                 return o.linearSolver == c.linearSolver;
               })) {
      contenders.push_back({"lm_" + c.linearSolver, "none", c.linearSolver, false});
    }
  }
  return contenders;
}

// Where a solve left the bounded parameters.
struct BoundsState {
  bool held = true;
  int atLimit = 0;           // parameters on a bound
  std::vector<double> gaps;  // per bound: distance to the nearer bound / half-width (0 on it, 1 at the centre)
};

BoundsState inspectBounds(const Bounds& bounds) {
  BoundsState state;
  for (const Bounds::Bound& bound : bounds.all()) {
    const double x = Bounds::value(bound);
    if (x < bound.lower || x > bound.upper) state.held = false;
    const double gap = std::min(x - bound.lower, bound.upper - x) / bound.halfWidth();
    if (gap <= kAtBound) ++state.atLimit;
    state.gaps.push_back(gap);
  }
  return state;
}

// One problem: a graph, its bounds and the start every solve begins from.
class BenchProblem {
 public:
  BenchProblem(std::string name, Graph& graph, const Bounds& bounds, nlohmann::ordered_json fields)
      : name_(std::move(name)), graph_(graph), bounds_(bounds), fields_(std::move(fields)), start_(graph.estimates()) {}
  const std::string& name() const { return name_; }
  const nlohmann::ordered_json& fields() const { return fields_; }
  Graph& graph() { return graph_; }
  const Bounds& bounds() const { return bounds_; }
  void restoreStart() { graph_.setEstimates(start_); }

 private:
  std::string name_;
  Graph& graph_;
  const Bounds& bounds_;
  nlohmann::ordered_json fields_;
  std::vector<double> start_;  // Graph::estimates()
};

// A row of the comparison with what this bench adds to the common one.
struct WindowRow {
  BenchRow bench;
  std::string method;
  std::string linearSolver;
  bool ignoresBounds = false;  // `none`, Ceres without bounds
  BoundsState bounds;          // after the last run
  bool heldInEveryRun = true;
  std::optional<double> ratioCostBest;  // final cost over the lowest final cost of a Ceres solve that kept the bounds
};

// Solves the problem's start once with the contender; returns the result and
// leaves the solution in the graph.
SolveResult solveOnce(const Contender& contender, BenchProblem& problem, const SolverOptions& stopping,
                      const BenchWindowOptions& o) {
  problem.restoreStart();
  if (contender.ceres) {
    const Bounds none;
    bench::CeresStereoModel model(problem.graph(), contender.withBounds ? problem.bounds() : none);
    const SolveResult result = model.solve(stopping, contender.ceresSolver);
    model.copyTo(problem.graph());
    const double cost = problem.graph().cost();
    if (std::abs(cost - result.finalCost) > kInitialCostTolerance * std::abs(result.finalCost))
      std::cerr << format(
          "[bench window] WARNING %s: Ceres reports final cost %.10e, our graph %.10e at its solution\n",
          problem.name().c_str(), result.finalCost, cost);
    return result;
  }
  SolverOptions options = stopping;
  if (!contender.linearSolver.empty()) options.linearSolver = contender.linearSolver;
  const Stopwatch stopwatch;
  const SolverSummary summary =
      optimizeWithBounds(problem.graph(), options, problem.bounds(), methodSpecification(contender.method, o));
  return bench::resultFromSummary(summary, stopwatch);
}

void runProblem(BenchProblem& problem, const std::vector<Contender>& contenders, const SolverOptions& stopping,
                const BenchWindowOptions& o, int repeat, int nloptRepeat, std::vector<WindowRow>& rows,
                std::vector<std::string>& failures) {
  for (const Contender& contender : contenders) {
    WindowRow row;
    row.method = contender.method;
    row.linearSolver = contender.linearSolver;
    row.ignoresBounds = contender.ignoresBounds();
    row.bench.problem = problem.name();
    row.bench.problemFields = problem.fields();
    row.bench.solver = contender.label;
    row.bench.family = contender.family();
    row.bench.reference = contender.ceres && contender.withBounds;  // what ours is measured against
    row.bench.jacobians = contender.ceres ? "autodiff" : "analytic";
    row.bench.threads = stopping.threads;
    const int runs = isNlopt(contender.method) ? nloptRepeat : repeat;
    try {
      row.bench.result = bench::medianRun(
          runs,
          [&] {
            const SolveResult result = solveOnce(contender, problem, stopping, o);
            row.bounds = inspectBounds(problem.bounds());
            row.heldInEveryRun = row.heldInEveryRun && row.bounds.held;
            return result;
          },
          [&](int run) {
            std::cerr << "[bench window] " << problem.name() << ": " << contender.label << ", run " << run << "/"
                      << runs << std::endl;
          });
    } catch (const Error& error) {  // one solver's failure is a result too; the others still run
      failures.push_back(problem.name() + " " + contender.label + ": " + error.what());
      std::cerr << "[bench window]   FAILED: " << error.what() << std::endl;
      continue;
    }
    std::cerr << format("[bench window]   %d iterations, %.4f s, final cost %.8e, bounds %s\n",
                        row.bench.result.iterations, row.bench.result.totalSeconds, row.bench.result.finalCost,
                        row.heldInEveryRun ? "held" : "VIOLATED");
    rows.push_back(std::move(row));
  }
}

// Ratios against Ceres for the rows of one problem, rows[first, end).
void computeRatios(std::vector<WindowRow>& rows, std::size_t first) {
  std::vector<BenchRow> benchRows;
  for (std::size_t i = first; i < rows.size(); ++i) benchRows.push_back(rows[i].bench);
  bench::computeRatios(benchRows, 0);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = first; i < rows.size(); ++i)
    if (rows[i].bench.reference && rows[i].heldInEveryRun) best = std::min(best, rows[i].bench.result.finalCost);
  for (std::size_t i = first; i < rows.size(); ++i) {
    rows[i].bench = benchRows[i - first];
    if (!rows[i].bench.reference && std::isfinite(best)) rows[i].ratioCostBest = rows[i].bench.result.finalCost / best;
  }
}

WindowProblemOptions windowOptions(const BenchWindowOptions& o, double altitude, int index) {
  WindowProblemOptions window;
  window.frames = o.frames;
  window.points = o.points;
  window.maxTrackLength = std::min(window.maxTrackLength, o.frames);
  window.minTrackLength = std::min(window.minTrackLength, window.maxTrackLength);
  window.altitude_m = altitude;
  window.pixelNoise = o.pixelNoise;
  window.seed = mixSeed(o.seed, static_cast<std::uint64_t>(index));
  window.trueOutsideBounds = o.active == "all" || (o.active == "alternate" && index % 2 == 1);
  return window;
}

std::string loadAverage() {
  double load[3];
  if (getloadavg(load, 3) != 3) return "unknown";
  return format("%.2f %.2f %.2f", load[0], load[1], load[2]);
}

std::string boundsCell(const WindowRow& row) {
  if (row.bounds.gaps.empty()) return "-";
  if (row.ignoresBounds) return row.heldInEveryRun ? "ignored, in" : "ignored, out";
  return row.heldInEveryRun ? "held" : "VIOLATED";
}

void printResults(const std::vector<WindowRow>& rows) {
  bench::TextTable table({"problem", "solver", "iterations", "median s", "cpu s", "final cost", "bounds", "at bound",
                          "time/Ceres", "time/fastest", "cost/Ceres best", "stop"});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const WindowRow& row = rows[i];
    const SolveResult& r = row.bench.result;
    if (i > 0 && row.bench.problem != rows[i - 1].bench.problem) table.addSeparator();
    table.addRow({row.bench.problem, row.bench.solver, std::to_string(r.iterations), format("%.4f", r.totalSeconds),
                  format("%.4f", r.cpuSeconds), format("%.8e", r.finalCost), boundsCell(row),
                  row.bounds.gaps.empty() ? "-" : std::to_string(row.bounds.atLimit),
                  bench::formatRatio(row.bench.ratioTime), bench::formatRatio(row.bench.ratioTimeFastest),
                  bench::formatRatio(row.ratioCostBest), r.termination});
  }
  table.print(std::cout);
}

// Per solver over all windows: how its time and cost compare with Ceres.
void printSolverSummary(const std::vector<WindowRow>& rows) {
  std::cout << "\nper solver over the windows (time/fastest: median and worst; cost/Ceres best: worst)\n";
  bench::TextTable table(
      {"solver", "windows", "median time/fastest", "worst time/fastest", "worst cost/Ceres best", "bounds held",
       format("goal met (>= %gx faster, cost <= +%.1f %%)", kGoalSpeedup, 100.0 * kFinalCostTolerance)});
  std::vector<std::string> solvers;
  for (const WindowRow& row : rows)
    if (row.bench.problem != kKittiProblem &&
        std::find(solvers.begin(), solvers.end(), row.bench.solver) == solvers.end())
      solvers.push_back(row.bench.solver);
  for (const std::string& solver : solvers) {
    std::vector<double> times;
    double worstCost = 0.0;
    int windows = 0, held = 0, goal = 0;
    bool ignoresBounds = false;
    for (const WindowRow& row : rows) {
      if (row.bench.solver != solver || row.bench.problem == kKittiProblem) continue;
      ++windows;
      ignoresBounds = row.ignoresBounds;
      held += row.heldInEveryRun ? 1 : 0;
      if (row.bench.ratioTimeFastest) times.push_back(*row.bench.ratioTimeFastest);
      if (row.ratioCostBest) worstCost = std::max(worstCost, *row.ratioCostBest);
      if (row.heldInEveryRun && row.bench.ratioTimeFastest && row.ratioCostBest &&
          *row.bench.ratioTimeFastest <= 1.0 / kGoalSpeedup && *row.ratioCostBest <= 1.0 + kFinalCostTolerance)
        ++goal;
    }
    std::sort(times.begin(), times.end());
    const bool ours = !times.empty();
    table.addRow({solver, std::to_string(windows), ours ? format("%.3f", times[(times.size() - 1) / 2]) : "-",
                  ours ? format("%.3f", times.back()) : "-", ours ? format("%.5f", worstCost) : "-",
                  format("%d/%d", held, windows), ours && !ignoresBounds ? format("%d/%d", goal, windows) : "-"});
  }
  table.print(std::cout);
}

// The paper's barrier against gradient projection on the same linear solver:
// iterations, time, cost, and how far the barrier stays from each bound that
// gradient projection ends on (in units of that bound's tolerance).
void printBarrierVersusProjection(const std::vector<WindowRow>& rows) {
  const char* const names[] = {"x", "y", "z", "roll", "pitch", "yaw"};  // the window's bounds, in order
  bench::TextTable table({"problem", "linear solver", "GP iterations", "LB iterations", "GP s", "LB s", "LB/GP time",
                          "LB cost/GP - 1", "LB gap to each bound GP ends on (of tolerance)"});
  int pairs = 0;
  for (const WindowRow& gp : rows) {
    if (gp.method != "gradient_projection" || gp.bounds.gaps.size() != std::size(names)) continue;
    const auto lb = std::find_if(rows.begin(), rows.end(), [&](const WindowRow& r) {
      return r.method == "log_barrier" && r.linearSolver == gp.linearSolver && r.bench.problem == gp.bench.problem;
    });
    if (lb == rows.end()) continue;
    ++pairs;
    std::string gaps;
    for (std::size_t k = 0; k < gp.bounds.gaps.size(); ++k)
      if (gp.bounds.gaps[k] <= kAtBound)
        gaps += format("%s%s %.1e", gaps.empty() ? "" : ", ", names[k], lb->bounds.gaps[k]);
    const SolveResult& a = gp.bench.result;
    const SolveResult& b = lb->bench.result;
    table.addRow({gp.bench.problem, gp.linearSolver, std::to_string(a.iterations), std::to_string(b.iterations),
                  format("%.4f", a.totalSeconds), format("%.4f", b.totalSeconds),
                  format("%.2f", b.totalSeconds / a.totalSeconds), format("%+.2e", b.finalCost / a.finalCost - 1.0),
                  gaps.empty() ? "-" : gaps});
  }
  if (pairs == 0) return;
  std::cout << "\nlog barrier (LB) against gradient projection (GP)\n";
  table.print(std::cout);
}

void printChecks(const std::vector<WindowRow>& rows, const std::vector<std::string>& failures) {
  std::cout << '\n';
  std::string lastProblem;
  for (const WindowRow& first : rows) {
    if (first.bench.problem == lastProblem) continue;
    lastProblem = first.bench.problem;
    const double reference = std::abs(first.bench.result.initialCost);
    double largest = 0.0;
    for (const WindowRow& row : rows)
      if (row.bench.problem == first.bench.problem)
        largest =
            std::max(largest, std::abs(row.bench.result.initialCost - first.bench.result.initialCost) / reference);
    std::cout << (largest <= kInitialCostTolerance
                      ? format("check %s: every solve starts at the same cost (largest relative difference %.1e)\n",
                               first.bench.problem.c_str(), largest)
                      : format("WARNING %s: initial costs differ by %.1e relative (> %.0e): the models do not match\n",
                               first.bench.problem.c_str(), largest, kInitialCostTolerance));
  }
  int flagged = 0, unbounded = 0, unboundedOutside = 0;
  for (const WindowRow& row : rows) {
    if (row.ignoresBounds && !row.bounds.gaps.empty()) ++unbounded;
    if (row.ignoresBounds) {
      unboundedOutside += row.heldInEveryRun ? 0 : 1;
    } else if (!row.heldInEveryRun) {
      ++flagged;
      std::cout << format("BOUNDS VIOLATED %s %s: the solution leaves the box\n", row.bench.problem.c_str(),
                          row.bench.solver.c_str());
    } else if (row.ratioCostBest && *row.ratioCostBest > 1.0 + kFinalCostTolerance) {
      ++flagged;
      std::cout << format("WORSE %s %s: final cost %.8e is %.3f %% above Ceres' best\n", row.bench.problem.c_str(),
                          row.bench.solver.c_str(), row.bench.result.finalCost, 100.0 * (*row.ratioCostBest - 1.0));
    }
  }
  if (unbounded > 0)
    std::cout << format(
        "note: 'none' and Ceres without bounds ignore the bounds; their solutions leave the box in %d of %d window "
        "solves\n",
        unboundedOutside, unbounded);
  for (const std::string& failure : failures) std::cout << "FAILED " << failure << '\n';
  if (flagged == 0 && failures.empty())
    std::cout << format(
        "check: every bounded solve of ours keeps its bounds and ends within %.1f %% of Ceres' best cost (or below)\n",
        100.0 * kFinalCostTolerance);
}

void printPreamble(const BenchWindowOptions& o, const SolverOptions& stopping) {
  std::cout << "lrsvo bench window: our constraint methods (LM, analytic Jacobians, multiplicative damping) against "
               "Ceres LEVENBERG_MARQUARDT (AutoDiff, jacobi scaling, points eliminated first, bounds through "
               "SetParameterLowerBound/UpperBound)\n"
            << format(
                   "windows: %d frames, %d points, pixel noise %g px, bounds +-1 mm / +-0.01 rad, %d per altitude, "
                   "seeds from %llu, true extrinsic outside the box: %s\n",
                   o.frames, o.points, o.pixelNoise, o.count, static_cast<unsigned long long>(o.seed), o.active.c_str())
            << format(
                   "stopping (both): function %.0e, gradient %.0e, parameter %.0e, at most %d iterations, "
                   "start lambda 1e-4, %d thread(s)\n",
                   stopping.functionTolerance, stopping.gradientTolerance, stopping.parameterTolerance,
                   stopping.maxIterations, stopping.threads)
            << describeMethod("log_barrier", o) << "; " << describeMethod("nlopt_lbfgs", o) << " (nlopt_*)\n"
            << format(
                   "times: wall time of the solve call, median of %d run(s) (KITTI %d, NLopt %d); cpu s = process "
                   "CPU time of that call\n",
                   o.repeat, o.kittiRepeat, o.nloptRepeat)
            << "load average at the start: " << loadAverage() << "\n\n";
}

void validate(const BenchWindowOptions& o) {
  if (o.count < 1) throw Error("bench window: --count must be at least 1");
  if (o.active != "alternate" && o.active != "all" && o.active != "none")
    throw Error("bench window: --active must be alternate, all or none");
  if (o.repeat < 1 || o.kittiRepeat < 1 || o.nloptRepeat < 1) throw Error("bench window: repeat counts must be >= 1");
  if (o.threads < 1 || o.maxIterations < 1) throw Error("bench window: --threads and --max-iterations must be >= 1");
  if (o.nloptEvaluations < 1 || o.nloptRounds < 1) throw Error("bench window: NLopt caps must be >= 1");
  for (const std::string& solver : o.linearSolvers)
    if (solver != "schur_dense" && solver != "schur_cholmod")
      throw Error("bench window: --linear-solvers takes schur_dense and schur_cholmod, not '" + solver + "'");
}

void runBenchWindow(const BenchWindowOptions& o) {
  validate(o);
  const std::vector<Contender> contenders = windowContenders(o);
  if (!o.json.empty()) bench::writeJson({}, o.json);  // fail now, not after the solves

  SolverOptions stopping;  // Ceres' default tolerances
  stopping.algorithm = "lm";
  stopping.maxIterations = o.maxIterations;
  stopping.threads = o.threads;
  printPreamble(o, stopping);

  std::vector<WindowRow> rows;
  std::vector<std::string> failures;  // solves that threw, with the reason
  for (double altitude : o.altitudes) {
    for (int index = 0; index < o.count; ++index) {
      const WindowProblemOptions options = windowOptions(o, altitude, index);
      WindowProblem window = makeWindowProblem(options);
      nlohmann::ordered_json fields;
      fields["altitude_m"] = altitude;
      fields["seed"] = options.seed;
      fields["frames"] = options.frames;
      fields["points"] = options.points;
      fields["observations"] = window.graph.edges().size();
      fields["true_outside_bounds"] = options.trueOutsideBounds;
      fields["position_tolerance_m"] = options.positionTolerance_m;
      fields["angle_tolerance_rad"] = options.angleTolerance_rad;
      const std::string name = format("window_%gm_%d%s", altitude, index, options.trueOutsideBounds ? "_active" : "");
      std::cout << format(
          "problem %s: %zu poses (first fixed), %zu points, %zu observations, true extrinsic %s the box\n",
          name.c_str(), window.poses.size(), window.points.size(), window.graph.edges().size(),
          options.trueOutsideBounds ? "outside" : "inside");
      BenchProblem problem(name, window.graph, window.extrinsicBounds, fields);
      const std::size_t first = rows.size();
      runProblem(problem, contenders, stopping, o, o.repeat, o.nloptRepeat, rows, failures);
      computeRatios(rows, first);
    }
  }

  const std::vector<Contender> kitti = kittiContenders(contenders);
  // A directory the user named must load (or fail loudly); the default one is optional.
  const bool kittiWanted = o.kitti && !kitti.empty();
  const bool kittiHere = o.kittiDirectoryGiven || std::filesystem::is_directory(o.kittiDirectory);
  if (kittiWanted && !kittiHere)
    std::cout << "problem " << kKittiProblem << ": left out, no " << o.kittiDirectory
              << " here (run from the repository's top, or give --kitti-dir)\n";
  if (kittiWanted && kittiHere) {
    StereoVoProblem vo = loadGtsamStereoVo(o.kittiDirectory);
    nlohmann::ordered_json fields;
    fields["poses"] = vo.poses.size();
    fields["points"] = vo.landmarkVertexIds.size();
    fields["observations"] = vo.graph.edges().size();
    std::cout << format(
        "problem %s: KITTI (%s), %zu poses (first fixed), %zu points, %d stereo factors as %zu edges, "
        "extrinsic fixed, no bounds\n",
        kKittiProblem, o.kittiDirectory.c_str(), vo.poses.size(), vo.landmarkVertexIds.size(), vo.factorCount,
        vo.graph.edges().size());
    const Bounds none;
    BenchProblem problem(kKittiProblem, vo.graph, none, fields);
    const std::size_t first = rows.size();
    runProblem(problem, kitti, stopping, o, o.kittiRepeat, o.kittiRepeat, rows, failures);
    computeRatios(rows, first);
  }

  std::cout << '\n';
  printResults(rows);
  printSolverSummary(rows);
  printBarrierVersusProjection(rows);
  printChecks(rows, failures);
  std::cout << "load average at the end: " << loadAverage() << '\n';
  if (o.json.empty()) return;
  std::vector<BenchRow> benchRows;
  for (const WindowRow& row : rows) benchRows.push_back(row.bench);
  nlohmann::ordered_json list = bench::rowsToJson(benchRows);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const WindowRow& row = rows[i];
    list[i]["method"] = row.method;
    list[i]["linear_solver"] = row.linearSolver;
    list[i]["median_time_s"] = row.bench.result.totalSeconds;
    list[i]["bounds_held"] = row.heldInEveryRun;
    list[i]["bounds_at_limit"] = row.bounds.atLimit;
    list[i]["bound_gaps"] = row.bounds.gaps;
    list[i]["ratio_cost_best"] =
        row.ratioCostBest ? nlohmann::ordered_json(*row.ratioCostBest) : nlohmann::ordered_json(nullptr);
  }
  bench::writeJsonValue(list, o.json);
  std::cout << "wrote " << o.json << '\n';
}

void addBenchWindow(CLI::App& app) {
  auto o = std::make_shared<BenchWindowOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "window", "Our constraint methods against Ceres on seeded stereo windows and the KITTI problem");
  command->add_option("--altitudes", o->altitudes, "Flight heights of the windows (m)")->capture_default_str();
  command
      ->add_option("--count", o->count,
                   "Windows per altitude, window_<altitude>m_<index>, each drawn from its own stream of --seed")
      ->capture_default_str();
  command
      ->add_option("--active", o->active,
                   "Which windows have their true extrinsic outside the box (active bounds): alternate (every "
                   "second), all, none")
      ->capture_default_str();
  command->add_option("--seed", o->seed, "First seed")->capture_default_str();
  command->add_option("--frames", o->frames, "Frames per window")->capture_default_str();
  command->add_option("--points", o->points, "Points per window")->capture_default_str();
  command->add_option("--pixel-noise", o->pixelNoise, "Measurement noise sigma (px)")->capture_default_str();
  command->add_option("--solvers", o->solvers,
                      "Run only these: constraint method names, DENSE_SCHUR, SPARSE_SCHUR (default: all)");
  command->add_option("--linear-solvers", o->linearSolvers, "Our linear solvers for the LM methods")
      ->capture_default_str();
  command->add_option("--threads", o->threads, "Threads of every solver")->capture_default_str();
  command->add_option("--max-iterations", o->maxIterations, "Iteration cap for both libraries")->capture_default_str();
  command->add_option("--repeat", o->repeat, "Runs per window solve; the median time is reported")
      ->capture_default_str();
  command->add_option("--kitti-repeat", o->kittiRepeat, "Runs per KITTI solve")->capture_default_str();
  command->add_option("--nlopt-repeat", o->nloptRepeat, "Runs per NLopt solve (slow)")->capture_default_str();
  command->add_option("--nlopt-evaluations", o->nloptEvaluations, "NLopt: cost evaluations per round")
      ->capture_default_str();
  command->add_option("--nlopt-rounds", o->nloptRounds, "NLopt: rounds (re-anchoring the poses)")
      ->capture_default_str();
  command->add_option("--barrier-mu", o->barrierMu, "log_barrier: starting mu (default: the method's)");
  command->add_option("--barrier-rounds", o->barrierRounds,
                      "log_barrier: rounds, mu x 0.1 after each (default: the method's)");
  command->add_flag("!--no-kitti", o->kitti, "Leave out the KITTI problem");
  CLI::Option* kittiDirectory =
      command
          ->add_option("--kitti-dir", o->kittiDirectory,
                       "Directory of the KITTI problem (GTSAM StereoVOExample); by default looked for relative to "
                       "the working directory, and left out when absent")
          ->capture_default_str();
  command->add_option("--json", o->json, "Also write the results as a JSON list to FILE");
  command->callback([o, kittiDirectory] {
    o->kittiDirectoryGiven = kittiDirectory->count() > 0;
    runBenchWindow(*o);
  });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench window", addBenchWindow);

}  // namespace lrsvo::cli
