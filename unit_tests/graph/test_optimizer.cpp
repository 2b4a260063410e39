// Levenberg-Marquardt and Gauss-Newton through Optimizer: monotone cost,
// agreement across linear solvers and threads, stopping rules, the summary.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/registry.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

ToyOptions noisyProblem(std::uint64_t seed, const std::string& kernel = "") {
  ToyOptions options;
  options.seed = seed;
  options.poses = 6;
  options.points = 50;
  options.sharedScale = seed % 2 == 0;
  options.poseNoise = 0.05;
  options.pointNoise = 0.3;
  options.outlierFraction = kernel.empty() ? 0.0 : 0.15;
  options.randomInformation = true;
  options.kernel = kernel;
  options.kernelDelta = 10.0;  // pixels; the 30-pixel outliers lie beyond it
  return options;
}

// Every record after the start: an accepted step lowered the cost, a rejected
// one left it unchanged; the graph ends at the reported final cost.
void expectMonotone(const SolverSummary& summary, const Graph& graph) {
  ASSERT_FALSE(summary.iterations.empty());
  EXPECT_EQ(summary.iterations.front().cost, summary.initialCost);
  double previous = summary.initialCost;
  for (std::size_t k = 1; k < summary.iterations.size(); ++k) {
    const IterationRecord& record = summary.iterations[k];
    if (record.accepted)
      EXPECT_LT(record.cost, previous) << "iteration " << record.iteration;
    else
      EXPECT_EQ(record.cost, previous) << "iteration " << record.iteration;
    previous = record.cost;
  }
  EXPECT_LE(summary.finalCost, summary.initialCost);
  EXPECT_NEAR(graph.cost(), summary.finalCost, 1e-12 * summary.initialCost);
}

TEST(Optimizer, LevenbergMarquardtNeverRaisesTheCost) {
  int rejected = 0;
  for (std::uint64_t seed : {1, 2, 3}) {
    for (Damping damping : {Damping::kMultiplicative, Damping::kAdditive}) {
      for (const char* kernel : {"", "Huber", "Cauchy", "Tukey", "cycle"}) {
        Graph graph = makeToyProblem(noisyProblem(seed, kernel));
        SolverOptions options;
        options.lm.damping = damping;
        // Tiny start lambdas: over-long steps are tried and rejected, which
        // exercises restoring the estimates.
        options.lm.initialLambda = damping == Damping::kAdditive ? 1e-6 : 1e-8;
        const SolverSummary summary = Optimizer(options).optimize(graph);
        SCOPED_TRACE(std::string("seed ") + std::to_string(seed) + ", kernel '" + kernel + "', " +
                     (damping == Damping::kAdditive ? "additive" : "multiplicative"));
        expectMonotone(summary, graph);
        // Tukey's zero weight beyond delta leaves the start's large errors where they are.
        EXPECT_LT(summary.finalCost, (std::string(kernel) == "Tukey" ? 1.0 : 0.5) * summary.initialCost);
        rejected += summary.unsuccessfulSteps;
      }
    }
  }
  EXPECT_GT(rejected, 0) << "no step was ever rejected: the test did not exercise restoring estimates";
}

// The direct solvers take the same steps up to rounding, so the same number of
// iterations ends at the same cost (the iterative ones, whose steps differ,
// are held to the minimum in test_iterative_schur.cpp).
TEST(Optimizer, FinalCostAgreesAcrossLinearSolvers) {
  for (bool bal : {false, true}) {
    double reference = -1.0;
    for (const auto& [name, entry] : Registry<LinearSolver>::instance().entries()) {
      if (!entry.factory()->exactSteps()) continue;
      BalToyOptions balOptions;
      balOptions.cameras = 5;
      balOptions.points = 40;
      balOptions.fixedCameras = 2;
      Graph graph = bal ? makeBalToyProblem(balOptions) : makeToyProblem(noisyProblem(4, "Huber"));
      SolverOptions options;
      options.linearSolver = name;
      options.functionTolerance = 1e-12;
      const SolverSummary summary = Optimizer(options).optimize(graph);
      if (reference < 0) reference = summary.finalCost;
      EXPECT_NEAR(summary.finalCost, reference, 1e-9 * reference) << name << (bal ? " on BAL" : "");
    }
  }
}

TEST(Optimizer, GaussNewtonAndLevenbergMarquardtReachTheSameMinimum) {
  ToyOptions problem;
  problem.sharedScale = true;
  problem.seed = 5;
  Graph gnGraph = makeToyProblem(problem);
  Graph lmGraph = makeToyProblem(problem);
  SolverOptions options;
  options.functionTolerance = 1e-14;
  options.maxIterations = 100;
  options.algorithm = "gn";
  const SolverSummary gn = Optimizer(options).optimize(gnGraph);
  options.algorithm = "lm";
  const SolverSummary lm = Optimizer(options).optimize(lmGraph);
  ASSERT_TRUE(gn.converged()) << gn.fullReport();
  ASSERT_TRUE(lm.converged()) << lm.fullReport();
  EXPECT_NEAR(gn.finalCost, lm.finalCost, 1e-8 * lm.finalCost);
  const std::vector<double> a = gnGraph.estimates(), b = lmGraph.estimates();
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-5) << "estimate " << k;
}

// Every pose fixed, only points move (structure-only refinement): the Schur
// solvers' reduced system is empty and must still give the point steps.
TEST(Optimizer, PointsOnlyRefinementWithEveryPoseFixed) {
  for (const auto& [name, entry] : Registry<LinearSolver>::instance().entries()) {
    ToyOptions problem;
    problem.fixedPoses = problem.poses;
    Graph graph = makeToyProblem(problem);
    SolverOptions options;
    options.linearSolver = name;
    const SolverSummary summary = Optimizer(options).optimize(graph);
    EXPECT_TRUE(summary.converged()) << summary.briefReport();
    EXPECT_LT(summary.finalCost, 0.5 * summary.initialCost) << name;
  }
}

SolverOptions withoutTolerances() {
  SolverOptions options;
  options.functionTolerance = 0.0;
  options.gradientTolerance = 0.0;
  options.parameterTolerance = 0.0;
  return options;
}

// The Jacobi-scaled damping floor only moves the floor: on a problem whose
// curvatures stay far above it the solve is the same (up to the rounding of
// the shift's product), the default one.
TEST(Optimizer, JacobiScaledDiagonalLeavesAWellCurvedSolveAsItIs) {
  for (const char* solver : {"lm_dense", "lm_schur_cholmod"}) {
    Graph plainGraph = makeToyProblem(noisyProblem(6));
    Graph scaledGraph = makeToyProblem(noisyProblem(6));
    SolverOptions options = SolverOptions::fromName(solver);
    options.functionTolerance = 1e-12;
    ASSERT_FALSE(options.lm.jacobiScaledDiagonal) << "the default damping floor is in the parameters' units";
    const SolverSummary plain = Optimizer(options).optimize(plainGraph);
    options.lm.jacobiScaledDiagonal = true;
    const SolverSummary scaled = Optimizer(options).optimize(scaledGraph);
    EXPECT_NEAR(scaled.finalCost, plain.finalCost, 1e-9 * plain.finalCost) << solver;
    EXPECT_NEAR(static_cast<double>(scaled.iterations.size()), static_cast<double>(plain.iterations.size()), 1.0)
        << solver;
    const std::vector<double> a = plainGraph.estimates(), b = scaledGraph.estimates();
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-6) << solver << " estimate " << k;
  }
}

TEST(Optimizer, MaxIterationsIsRespected) {
  for (const char* algorithm : {"lm", "gn"}) {
    for (int cap : {0, 1, 3}) {
      Graph graph = makeToyProblem(noisyProblem(6));
      SolverOptions options = withoutTolerances();
      options.algorithm = algorithm;
      options.maxIterations = cap;
      const SolverSummary summary = Optimizer(options).optimize(graph);
      EXPECT_EQ(summary.termination, Termination::kMaxIterations) << algorithm << " cap " << cap;
      EXPECT_EQ(summary.iterationCount(), cap) << algorithm;
    }
  }
}

TEST(Optimizer, TimeBudgetStopsTheSolve) {
  for (const char* algorithm : {"lm", "gn"}) {
    Graph graph = makeToyProblem(noisyProblem(7));
    SolverOptions options = withoutTolerances();
    options.algorithm = algorithm;
    options.maxSeconds = 1e-12;
    const SolverSummary summary = Optimizer(options).optimize(graph);
    EXPECT_EQ(summary.termination, Termination::kTimeLimit) << algorithm;
    EXPECT_EQ(summary.iterationCount(), 0) << algorithm;
    EXPECT_EQ(summary.finalCost, summary.initialCost) << algorithm;
  }
}

TEST(Optimizer, StartAtTheOptimumStopsOnTheGradient) {
  for (const char* algorithm : {"lm", "gn"}) {
    ToyOptions problem;
    problem.sharedScale = true;
    problem.pixelNoise = problem.poseNoise = problem.pointNoise = problem.scaleNoise = 0.0;
    Graph graph = makeToyProblem(problem);
    const std::vector<double> start = graph.estimates();
    SolverOptions options;
    options.algorithm = algorithm;
    const SolverSummary summary = Optimizer(options).optimize(graph);
    EXPECT_EQ(summary.termination, Termination::kGradientTolerance) << algorithm;
    EXPECT_EQ(summary.iterationCount(), 0) << algorithm;
    EXPECT_LT(summary.finalCost, 1e-20) << algorithm;
    EXPECT_EQ(graph.estimates(), start) << algorithm;
  }
}

TEST(Optimizer, FunctionToleranceEndsAConvergedSolve) {
  Graph graph = makeToyProblem(noisyProblem(8));
  const SolverSummary summary = Optimizer().optimize(graph);
  EXPECT_EQ(summary.termination, Termination::kFunctionTolerance) << summary.fullReport();
  const IterationRecord& last = summary.iterations.back();
  EXPECT_TRUE(last.accepted);
  EXPECT_LE(last.costChange / (last.cost + last.costChange), 1e-6);
}

// The graph's cost on threads adds the edges' costs in edge order, as one
// thread does: the same value to the last bit, over several chunks of edges.
TEST(Graph, CostIsTheSameOnAnyThreadCount) {
  ToyOptions problem;
  problem.points = 150;
  problem.kernel = "cycle";
  problem.outlierFraction = 0.2;
  const Graph graph = makeToyProblem(problem);
  double inOrder = 0.0;
  for (const auto& edge : graph.edges()) inOrder += edge->cost();
  EXPECT_EQ(graph.cost(), inOrder);
  EXPECT_EQ(graph.cost(2), inOrder);
  EXPECT_EQ(graph.cost(3), inOrder);
  EXPECT_THROW(graph.cost(0), Error);
}

TEST(Optimizer, TwoThreadsGiveTheSameResultAsOne) {
  for (const char* solver : {"schur_cholmod", "schur_dense", "cholmod"}) {
    double costs[2];
    std::vector<double> estimates[2];
    for (int threads : {1, 2}) {
      BalToyOptions problem;
      problem.cameras = 6;
      problem.points = 150;  // several parallel chunks (of 64) of edges and points
      problem.kernel = "cycle";
      Graph graph = makeBalToyProblem(problem);
      SolverOptions options;
      options.linearSolver = solver;
      options.threads = threads;
      options.maxIterations = 5;
      const SolverSummary summary = Optimizer(options).optimize(graph);
      EXPECT_EQ(summary.threads, threads);
      costs[threads - 1] = summary.finalCost;
      estimates[threads - 1] = graph.estimates();
    }
    EXPECT_NEAR(costs[1], costs[0], 1e-9 * costs[0]) << solver;
    for (std::size_t k = 0; k < estimates[0].size(); ++k)
      ASSERT_NEAR(estimates[1][k], estimates[0][k], 1e-6 * (std::abs(estimates[0][k]) + 1.0)) << solver << " " << k;
  }
}

TEST(Optimizer, SummaryRecordsAreConsistent) {
  for (const char* algorithm : {"lm", "gn"}) {
    Graph graph = makeToyProblem(noisyProblem(9, "Cauchy"));
    SolverOptions options;
    options.algorithm = algorithm;
    options.lm.initialLambda = 1e-9;  // provokes rejected LM steps
    const SolverSummary summary = Optimizer(options).optimize(graph);
    SCOPED_TRACE(algorithm);
    ASSERT_GE(summary.iterationCount(), 2) << summary.fullReport();
    int accepted = 0;
    for (int k = 0; k <= summary.iterationCount(); ++k) {
      const IterationRecord& record = summary.iterations[k];
      EXPECT_EQ(record.iteration, k);
      accepted += record.accepted;
      EXPECT_GE(record.iterationSeconds, 0.0);
      if (k > 0) {
        EXPECT_GE(record.cumulativeSeconds, summary.iterations[k - 1].cumulativeSeconds);
        EXPECT_GT(record.stepNorm, 0.0);
      }
    }
    EXPECT_EQ(accepted, summary.successfulSteps);
    EXPECT_LE(summary.successfulSteps + summary.unsuccessfulSteps, summary.iterationCount());
    EXPECT_GE(summary.successfulSteps + summary.unsuccessfulSteps, summary.iterationCount() - 1);
    EXPECT_NEAR(summary.iterations.back().cost, summary.finalCost, 1e-12 * summary.finalCost);
    EXPECT_EQ(summary.solver, std::string(algorithm) + "_schur_cholmod");
    EXPECT_EQ(summary.edgeCount, static_cast<int>(graph.edges().size()));
    EXPECT_GE(summary.totalSeconds, summary.iterations.back().cumulativeSeconds);
    EXPECT_NE(summary.briefReport().find(terminationName(summary.termination)), std::string::npos);
  }
}

TEST(Optimizer, SummaryJsonHasTheRequiredFields) {
  Graph graph = makeToyProblem(noisyProblem(10));
  const SolverSummary summary = Optimizer().optimize(graph);
  const nlohmann::json json = nlohmann::json::parse(summary.toJson());
  ASSERT_TRUE(json.is_object());
  for (const char* key : {"initial_cost", "final_cost", "iterations", "total_time_s", "termination"})
    ASSERT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["initial_cost"].get<double>(), summary.initialCost);
  EXPECT_EQ(json["final_cost"].get<double>(), summary.finalCost);
  EXPECT_EQ(json["iterations"].get<int>(), summary.iterationCount());
  EXPECT_EQ(json["total_time_s"].get<double>(), summary.totalSeconds);
  EXPECT_EQ(json["termination"].get<std::string>(), terminationName(summary.termination));
  ASSERT_TRUE(json.contains("iteration_log"));
  EXPECT_EQ(json["iteration_log"].size(), summary.iterations.size());
}

// The summary says how the (reduced) system was factorised: the dense back
// end has no ordering and takes n^3 / 3 flops for the n unknowns of the poses
// and the shared scale; CHOLMOD names its ordering and counts at least the
// diagonal's n flops; an iterative solver factorises nothing.
TEST(Optimizer, SummaryNamesTheFactorisation) {
  const ToyOptions problem = noisyProblem(2);  // even seed: a shared scale
  ASSERT_TRUE(problem.sharedScale);
  const double reduced = 6.0 * (problem.poses - problem.fixedPoses) + 1.0;
  for (const char* name : {"lm_schur_dense", "lm_schur_cholmod", "lm_schur_pcg"}) {
    SCOPED_TRACE(name);
    Graph graph = makeToyProblem(problem);
    const SolverSummary summary = Optimizer(SolverOptions::fromName(name)).optimize(graph);
    const nlohmann::json json = nlohmann::json::parse(summary.toJson());
    EXPECT_EQ(json["ordering"].get<std::string>(), summary.ordering);
    EXPECT_EQ(json["factorization_flops"].get<double>(), summary.factorizationFlops);
    if (std::string(name) == "lm_schur_dense") {
      EXPECT_EQ(summary.ordering, "dense");
      EXPECT_DOUBLE_EQ(summary.factorizationFlops, reduced * reduced * reduced / 3.0);
    } else if (std::string(name) == "lm_schur_cholmod") {
      EXPECT_FALSE(summary.ordering.empty());
      EXPECT_GE(summary.factorizationFlops, reduced);
      EXPECT_NE(summary.fullReport().find(summary.ordering + " ordering"), std::string::npos);
    } else {
      EXPECT_TRUE(summary.ordering.empty());
      EXPECT_EQ(summary.factorizationFlops, 0.0);
    }
  }
}

}  // namespace
}  // namespace lrsvo::test
