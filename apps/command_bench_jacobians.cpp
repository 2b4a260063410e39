// `lrsvo bench jacobians`: hand-written, automatic (dual numbers) and numeric
// Jacobians side by side on the BAL and stereo projection edges: time per
// linearisation, agreement, and a whole BAL solve each way.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "apps/bench/bench_common.h"
#include "apps/command.h"
#include "lrsvo/edges/edge_bal_projection.h"
#include "lrsvo/edges/edge_project_base.h"
#include "lrsvo/edges/edge_project_secondary.h"
#include "lrsvo/frontend/datasets/bal_problem.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/seed_mix.h"
#include "lrsvo/graph/stopwatch.h"
#include "lrsvo/vertices/so3.h"

namespace lrsvo::cli {
namespace {

constexpr std::uint64_t kStereoStream = 0x5e5e0;  // mixSeed label of the stereo states

enum class Method { kHandWritten, kAutoDiff, kEigenAutoDiff, kCentral, kRidders };
constexpr Method kMethods[] = {Method::kHandWritten, Method::kAutoDiff, Method::kEigenAutoDiff, Method::kCentral,
                               Method::kRidders};

const char* methodName(Method method) {
  switch (method) {
    case Method::kHandWritten: return "hand-written";
    case Method::kAutoDiff: return "autodiff";
    case Method::kEigenAutoDiff: return "eigen-autodiff";
    case Method::kCentral: return "central";
    case Method::kRidders: return "ridders";
  }
  return "";
}

struct BenchJacobiansOptions {
  int cameras = 50;
  int points = 10000;
  int stereoEdges = 20000;
  int repeat = 5;
  std::uint64_t seed = 1;
};

// Wraps an edge type so its numeric Jacobians use the method asked for.
template <typename EdgeType>
class WithNumericMethod : public EdgeType {
 public:
  using EdgeType::EdgeType;
  NumericDifference method = NumericDifference::kCentral;
  NumericDiffOptions numericDiffOptions() const override { return {.method = method}; }
};

// What a linearisation of the edge costs with each method: residual and
// Jacobians. Dual numbers give both in one evaluation; the others evaluate the
// residual in double beside them.
template <typename EdgeType>
void evaluate(WithNumericMethod<EdgeType>& edge, Method method) {
  typename EdgeType::Residual residual;
  switch (method) {
    case Method::kHandWritten:
      edge.computeResidual(residual);
      edge.computeJacobians();
      break;
    case Method::kAutoDiff: edge.computeAutoDiffResidualAndJacobians(residual); break;
    case Method::kEigenAutoDiff:
      edge.computeResidual(residual);
      edge.template computeAutoDiffJacobiansWith<
          Eigen::AutoDiffScalar<Eigen::Matrix<double, EdgeType::kTangentDimension, 1>>>();
      break;
    case Method::kCentral:
    case Method::kRidders:
      edge.computeResidual(residual);
      edge.method = method == Method::kRidders ? NumericDifference::kRidders : NumericDifference::kCentral;
      edge.computeNumericJacobians();
      break;
  }
}

// Jacobians of every vertex of an edge side by side, as one matrix.
template <typename EdgeType>
Eigen::MatrixXd allJacobians(const EdgeType& edge) {
  if constexpr (EdgeType::kVertexCount == 2) {
    Eigen::MatrixXd j(EdgeType::kResidualDim, edge.template jacobian<0>().cols() + edge.template jacobian<1>().cols());
    j << edge.template jacobian<0>(), edge.template jacobian<1>();
    return j;
  } else {
    Eigen::MatrixXd j(EdgeType::kResidualDim, edge.template jacobian<0>().cols() + edge.template jacobian<1>().cols() +
                                                  edge.template jacobian<2>().cols());
    j << edge.template jacobian<0>(), edge.template jacobian<1>(), edge.template jacobian<2>();
    return j;
  }
}

// Times residual + Jacobians over all edges (median of `repeat` passes) and
// compares each method's Jacobians with the hand-written ones.
template <typename EdgeType>
void compareMethods(const char* name, const std::vector<WithNumericMethod<EdgeType>*>& edges, int repeat) {
  std::printf("\n%s: %zu edges, residual + Jacobians per edge\n", name, edges.size());
  std::printf("%-14s %14s %12s %26s\n", "Jacobians", "ns per edge", "vs hand", "max |J - J_hand| / |J_hand|");
  double handWritten = 0.0;
  for (Method method : kMethods) {
    std::vector<double> passes;
    for (int pass = 0; pass < repeat; ++pass) {
      const Stopwatch stopwatch;
      for (auto* edge : edges) evaluate(*edge, method);
      passes.push_back(stopwatch.seconds());
    }
    std::sort(passes.begin(), passes.end());
    const double nanoseconds = passes[passes.size() / 2] / static_cast<double>(edges.size()) * 1e9;
    if (method == Method::kHandWritten) handWritten = nanoseconds;
    double worst = 0.0;
    for (auto* edge : edges) {
      evaluate(*edge, Method::kHandWritten);
      const Eigen::MatrixXd reference = allJacobians(*edge);
      evaluate(*edge, method);
      worst = std::max(worst, (allJacobians(*edge) - reference).norm() / reference.norm());
    }
    std::printf("%-14s %14.1f %12.2f %26.2e\n", methodName(method), nanoseconds, nanoseconds / handWritten, worst);
  }
}

void benchBalEdges(const BenchJacobiansOptions& o, const BalProblem& problem) {
  Graph graph = makeBalGraph(problem, "", 1.0, [] { return std::make_unique<WithNumericMethod<EdgeBalProjection>>(); });
  std::vector<WithNumericMethod<EdgeBalProjection>*> edges;
  for (const auto& edge : graph.edges())
    edges.push_back(static_cast<WithNumericMethod<EdgeBalProjection>*>(edge.get()));
  compareMethods("BAL reprojection (camera 9 + point 3)", edges, o.repeat);
}

void benchStereoEdges(const BenchJacobiansOptions& o) {
  std::mt19937_64 rng(mixSeed(o.seed, kStereoStream));
  std::normal_distribution<double> n(0.0, 1.0);
  const PinholeIntrinsics intrinsics{1670.0, 1660.0, 640.0, 480.0};
  VertexStereoExtrinsic extrinsic(0);
  VertexStereoExtrinsic::Vector6 s;
  s << 0.0, 0.7, 0.0, 0.01, -0.02, 0.005;
  extrinsic.setEstimateVector(s);
  std::vector<std::unique_ptr<VertexPose>> poses;
  std::vector<std::unique_ptr<VertexPoint3>> points;
  std::vector<std::unique_ptr<WithNumericMethod<EdgeProjectSecondary>>> owned;
  std::vector<WithNumericMethod<EdgeProjectSecondary>*> edges;
  for (int i = 0; i < o.stereoEdges; ++i) {
    Eigen::Isometry3d cameraFromWorld = Eigen::Isometry3d::Identity();
    cameraFromWorld.linear() = expSO3(Eigen::Vector3d(0.2 * n(rng), 0.2 * n(rng), 3.0 * n(rng)));
    cameraFromWorld.translation() = Eigen::Vector3d(50 * n(rng), 50 * n(rng), 100.0 + 10 * n(rng));
    poses.push_back(std::make_unique<VertexPose>(1 + 2 * i, cameraFromWorld));
    const Eigen::Vector3d inCamera(20 * n(rng), 20 * n(rng), 100.0 + 20 * std::abs(n(rng)));
    points.push_back(std::make_unique<VertexPoint3>(2 + 2 * i, cameraFromWorld.inverse() * inCamera));
    auto edge = std::make_unique<WithNumericMethod<EdgeProjectSecondary>>(SecondaryCamera{1, intrinsics});
    edge->setVertex(0, poses.back().get());
    edge->setVertex(1, points.back().get());
    edge->setVertex(2, &extrinsic);
    edges.push_back(edge.get());
    owned.push_back(std::move(edge));
  }
  compareMethods("Stereo secondary projection (pose 6 + point 3 + extrinsic 6)", edges, o.repeat);
}

// The whole solve of a generated BAL problem with hand-written and with
// dual-number Jacobians, `repeat` times each in turn (so neither gets the
// cold caches of the first solve); the median of each.
void benchBalSolve(const BalProblem& problem, int repeat) {
  std::printf("\nBAL solve, lm_schur_cholmod, 1 thread, same start, median of %d solves each, in turn\n", repeat);
  std::printf("%-14s %12s %14s %12s %12s %20s\n", "Jacobians", "iterations", "linearise s", "total s", "vs hand",
              "final cost");
  const std::vector<Method> methods = {Method::kHandWritten, Method::kAutoDiff};
  std::vector<std::vector<SolverSummary>> runs(methods.size());
  for (int pass = 0; pass < repeat; ++pass) {
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const Method method = methods[m];
      Graph graph = makeBalGraph(problem, "", 1.0, [method]() -> std::unique_ptr<EdgeBalProjection> {
        struct ByAutoDiff : EdgeBalProjection {
          void computeJacobians() override { computeAutoDiffJacobians(); }
        };
        if (method == Method::kAutoDiff) return std::make_unique<ByAutoDiff>();
        return std::make_unique<EdgeBalProjection>();
      });
      runs[m].push_back(Optimizer(SolverOptions::fromName("lm_schur_cholmod")).optimize(graph));
    }
  }
  auto median = [](std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
  };
  double handWrittenSeconds = 0.0;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::vector<double> linearise, total;
    for (const SolverSummary& summary : runs[m]) {
      linearise.push_back(summary.linearizeSeconds);
      total.push_back(summary.totalSeconds);
    }
    const double totalSeconds = median(total);
    if (methods[m] == Method::kHandWritten) handWrittenSeconds = totalSeconds;
    std::printf("%-14s %12d %14.3f %12.3f %12.2f %20.12e\n", methodName(methods[m]), runs[m].front().iterationCount(),
                median(linearise), totalSeconds, totalSeconds / handWrittenSeconds, runs[m].front().finalCost);
  }
}

void run(const BenchJacobiansOptions& o) {
  BalGeneratorOptions generator;
  generator.cameras = o.cameras;
  generator.points = o.points;
  generator.seed = o.seed;
  const BalProblem problem = generateBalProblem(generator);
  std::printf(
      "Jacobians: hand-written, automatic (lrsvo Dual; Eigen AutoDiffScalar beside it), numeric (relative steps);\n"
      "median of %d passes, 1 thread\n",
      o.repeat);
  benchBalEdges(o, problem);
  benchStereoEdges(o);
  benchBalSolve(problem, o.repeat);
}

void addBenchJacobians(CLI::App& app) {
  auto options = std::make_shared<BenchJacobiansOptions>();
  CLI::App* command = bench::benchSubcommand(app).add_subcommand(
      "jacobians", "Hand-written, automatic and numeric Jacobians on the BAL and stereo edges");
  command->add_option("--cameras", options->cameras, "Cameras of the generated BAL problem")->capture_default_str();
  command->add_option("--points", options->points, "Points of the generated BAL problem")->capture_default_str();
  command->add_option("--stereo-edges", options->stereoEdges, "Stereo projection edges, random long-range states")
      ->capture_default_str();
  command->add_option("--repeat", options->repeat, "Timed passes per method (the median is shown)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--seed", options->seed, "Random seed")->capture_default_str();
  command->callback([options] { run(*options); });
}

}  // namespace

LRSVO_REGISTER_COMMAND("bench jacobians", addBenchJacobians);

}  // namespace lrsvo::cli
