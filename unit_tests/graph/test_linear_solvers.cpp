// The normal equations the block system assembles, and every registered
// linear solver against a dense Cholesky reference on the same system.

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include "lrsvo/graph/base_edge.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/schur_solver.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

std::vector<std::string> registeredSolvers() {
  std::vector<std::string> names;
  for (const auto& [name, entry] : Registry<LinearSolver>::instance().entries()) names.push_back(name);
  return names;
}

TEST(LinearSolvers, TheBuiltInSolversAreRegistered) {
  const std::vector<std::string> names = registeredSolvers();
  for (const char* expected : {"dense", "cholmod", "schur_dense", "schur_cholmod", "schur_pcg", "schur_power_series"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

// Cost of the graph after moving block `i`'s coordinate `d` by `step`.
double costAfterStep(const Graph& graph, const BlockSystem& system, int i, int d, double step) {
  Vertex* vertex = system.vertex(i);
  std::vector<double> saved(vertex->estimateSize());
  vertex->getEstimate(saved.data());
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(vertex->dimension());
  delta[d] = step;
  vertex->oplus(delta.data());
  const double cost = graph.cost();
  vertex->setEstimate(saved.data());
  return cost;
}

// The gradient is that of the cost, d(sum 1/2 rho)/d delta, robust kernels included.
TEST(BlockSystem, GradientIsTheCostsDerivative) {
  for (const std::string kernel : {"", "cycle"}) {
    ToyOptions options;
    options.poses = 4;
    options.points = 12;
    options.sharedScale = true;
    options.fixedPoses = 1;
    options.fixedPoints = 2;
    options.randomInformation = true;
    options.outlierFraction = 0.2;
    options.kernel = kernel;
    Graph graph = makeToyProblem(options);
    BlockSystem system(graph, true);
    const double cost = system.fill(1);
    EXPECT_NEAR(cost, graph.cost(), 1e-12 * cost);
    constexpr double kStep = 1e-6;
    for (int i = 0; i < system.blockCount(); ++i) {
      for (int d = 0; d < system.dim(i); ++d) {
        const double numeric =
            (costAfterStep(graph, system, i, d, kStep) - costAfterStep(graph, system, i, d, -kStep)) / (2 * kStep);
        const double analytic = system.gradient()[system.offset(i) + d];
        EXPECT_NEAR(analytic, numeric, 1e-5 * (std::abs(numeric) + 1.0))
            << "kernel '" << kernel << "', vertex " << system.vertex(i)->id() << " coordinate " << d;
      }
    }
  }
}

// The Schur ordering sums the free vertices' shares of edges on points in the
// points' column passes, split into ranges of partial sums; the natural
// ordering sums every block from its own edges. Both must give the same H, g
// and diagonal up to the rounding of sums taken in another order: each entry
// sums at most a few hundred products, so the two differ by a few hundred
// units of rounding of its largest terms, far below 1e-12 of H's largest entry.
TEST(BlockSystem, SchurOrderingSumsTheSameSystem) {
  ToyOptions options;
  options.points = 400;  // enough columns of points for several ranges of partial sums
  options.sharedScale = true;
  options.fixedPoints = 3;
  options.randomInformation = true;
  options.kernel = "cycle";
  options.outlierFraction = 0.1;
  Graph graph = makeToyProblem(options);
  BlockSystem natural(graph, false), schur(graph, true);
  natural.fill(1);
  schur.fill(2);
  ASSERT_EQ(natural.scalarCount(), schur.scalarCount());

  // Scalar index in the natural system of each scalar of the Schur-ordered one.
  std::vector<int> toNatural(static_cast<std::size_t>(schur.scalarCount()));
  for (int i = 0; i < schur.blockCount(); ++i) {
    const int j = natural.blockOf(schur.vertex(i));
    ASSERT_GE(j, 0);
    for (int d = 0; d < schur.dim(i); ++d)
      toNatural[static_cast<std::size_t>(schur.offset(i) + d)] = natural.offset(j) + d;
  }
  const Eigen::MatrixXd hNatural = denseHessian(natural), hSchur = denseHessian(schur);
  const double scale = hNatural.cwiseAbs().maxCoeff();
  double largestDifference = 0.0;
  for (int a = 0; a < schur.scalarCount(); ++a) {
    const int na = toNatural[static_cast<std::size_t>(a)];
    EXPECT_NEAR(schur.gradient()[a], natural.gradient()[na], 1e-12 * natural.gradient().cwiseAbs().maxCoeff());
    EXPECT_EQ(schur.diagonal()[a], hSchur(a, a));
    for (int b = 0; b < schur.scalarCount(); ++b)
      largestDifference =
          std::max(largestDifference, std::abs(hSchur(a, b) - hNatural(na, toNatural[static_cast<std::size_t>(b)])));
  }
  EXPECT_LE(largestDifference, 1e-12 * scale);
}

// Each block of H sums its edges' shares in the order of the graph's edges,
// whatever order the set-up finds them in, so a solve is the same bit for bit
// however the structure is sorted. Here every edge is on the shared scale,
// last in the order: its column holds a pair of each edge, the rows (the
// edge's pose and point) alternating, and is sorted by row before it is
// summed. The reference adds each edge's blocks in edge order with the edge's
// own kernel, so the two must agree exactly.
TEST(BlockSystem, SumsEveryBlockInEdgeOrder) {
  ToyOptions options;
  options.poses = 8;
  options.points = 60;
  options.posesPerPoint = 5;
  options.sharedScale = true;
  options.fixedPoses = 1;
  options.randomInformation = true;
  options.kernel = "cycle";
  options.outlierFraction = 0.2;
  Graph graph = makeToyProblem(options);
  BlockSystem system(graph, false);
  system.fill(1);

  std::map<std::pair<int, int>, std::vector<double>> reference;  // (row, col) block -> values, column-major
  for (const auto& edge : graph.edges()) {
    edge->linearize();
    for (int a = 0; a < edge->vertexCount(); ++a)
      for (int b = 0; b < edge->vertexCount(); ++b) {
        const int row = system.blockOf(edge->vertex(a)), col = system.blockOf(edge->vertex(b));
        if (row < 0 || col < 0 || row > col) continue;
        std::vector<double>& values = reference[{row, col}];
        values.resize(static_cast<std::size_t>(system.dim(row) * system.dim(col)), 0.0);
        edge->addHessianBlock(a, b, values.data(), system.dim(row));
      }
  }
  ASSERT_EQ(reference.size(), system.blocks().size());
  for (const BlockSystem::Block& block : system.blocks()) {
    const auto found = reference.find({block.row, block.col});
    ASSERT_NE(found, reference.end()) << "block (" << block.row << ", " << block.col << ")";
    const std::vector<double>& expected = found->second;
    for (std::size_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(system.values(block)[i], expected[i]) << "block (" << block.row << ", " << block.col << ")";
  }
}

// At a zero-residual point the Gauss-Newton H is the exact Hessian of the cost.
TEST(BlockSystem, HessianAtAZeroResidualIsTheCostsSecondDerivative) {
  ToyOptions options;
  options.poses = 3;
  options.points = 8;
  options.sharedScale = true;
  options.fixedPoses = 1;
  options.pixelNoise = 0.0;
  options.poseNoise = options.pointNoise = options.scaleNoise = 0.0;
  options.randomInformation = true;
  Graph graph = makeToyProblem(options);
  ASSERT_LT(graph.cost(), 1e-20);
  BlockSystem system(graph, false);
  system.fill(1);
  const Eigen::MatrixXd h = denseHessian(system);

  // Second differences through the vertices' own updates.
  constexpr double kStep = 1e-4;
  const int n = system.scalarCount();
  std::vector<std::pair<int, int>> coordinates;
  for (int i = 0; i < system.blockCount(); ++i)
    for (int d = 0; d < system.dim(i); ++d) coordinates.emplace_back(i, d);
  auto costAt = [&](int a, double sa, int b, double sb) {
    std::vector<std::vector<double>> saved;
    for (int i = 0; i < system.blockCount(); ++i) {
      saved.emplace_back(system.vertex(i)->estimateSize());
      system.vertex(i)->getEstimate(saved.back().data());
    }
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(n);
    dx[a] += sa;
    dx[b] += sb;
    for (int i = 0; i < system.blockCount(); ++i) system.vertex(i)->oplus(dx.data() + system.offset(i));
    const double cost = graph.cost();
    for (int i = 0; i < system.blockCount(); ++i) system.vertex(i)->setEstimate(saved[i].data());
    return cost;
  };
  Eigen::MatrixXd numeric(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = a; b < n; ++b)
      numeric(a, b) = numeric(b, a) = (costAt(a, kStep, b, kStep) - costAt(a, kStep, b, -kStep) -
                                       costAt(a, -kStep, b, kStep) + costAt(a, -kStep, b, -kStep)) /
                                      (4 * kStep * kStep);
  EXPECT_LE((h - numeric).norm(), 1e-5 * h.norm());
}

// Solves the filled, shifted system with every registered direct solver and
// compares with a dense LLT of H built from the blocks (the iterative ones,
// exact only to their tolerances, have tests of their own).
void expectSolversMatchDenseReference(const Graph& graph, double relativeShift) {
  BlockSystem system(graph, /*schurOrdering=*/true);
  system.fill(1);
  system.setDiagonalShift(relativeShift * system.diagonal() + Eigen::VectorXd::Constant(system.scalarCount(), 1e-6));
  const Eigen::MatrixXd h = denseHessian(system);
  const Eigen::VectorXd rhs = -system.gradient();
  const Eigen::LLT<Eigen::MatrixXd> llt(h);
  ASSERT_EQ(llt.info(), Eigen::Success);
  const Eigen::VectorXd reference = llt.solve(rhs);
  ASSERT_GT(reference.norm(), 0.0);
  EXPECT_LE((system.multiply(reference) - rhs).norm(), 1e-9 * rhs.norm());

  for (const std::string& name : registeredSolvers()) {
    for (int threads : {1, 2}) {
      std::unique_ptr<LinearSolver> solver = Registry<LinearSolver>::instance().create(name);
      if (!solver->exactSteps()) continue;
      solver->analyze(system);
      Eigen::VectorXd x;
      ASSERT_TRUE(solver->solve(system, rhs, x, threads)) << name;
      ASSERT_EQ(x.size(), reference.size()) << name;
      EXPECT_LE((x - reference).norm(), 1e-9 * reference.norm()) << name << ", " << threads << " threads";
    }
  }
}

TEST(LinearSolvers, SameStepOnPosesAndPoints) {
  for (std::uint64_t seed : {1, 2, 3}) {
    ToyOptions options;
    options.seed = seed;
    options.poses = 7;
    options.points = 50;
    options.fixedPoses = 0;
    options.randomInformation = true;
    options.kernel = "cycle";
    options.outlierFraction = 0.1;
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectSolversMatchDenseReference(makeToyProblem(options), 1e-2);
  }
}

TEST(LinearSolvers, SameStepWithFixedPosesAndPoints) {
  ToyOptions options;
  options.poses = 6;
  options.points = 40;
  options.fixedPoses = 2;
  options.fixedPoints = 5;
  expectSolversMatchDenseReference(makeToyProblem(options), 1e-3);
}

TEST(LinearSolvers, SameStepWithASharedVertex) {
  ToyOptions options;
  options.poses = 8;
  options.points = 60;
  options.sharedScale = true;
  options.fixedPoses = 1;
  options.fixedPoints = 3;
  expectSolversMatchDenseReference(makeToyProblem(options), 1e-3);
}

TEST(LinearSolvers, SameStepOnBalCameras) {
  BalToyOptions options;
  options.cameras = 5;
  options.points = 40;
  options.randomInformation = true;
  expectSolversMatchDenseReference(makeBalToyProblem(options), 1e-2);
}

// The Schur solvers split the rows of S among threads, and every block of S
// takes its updates in the same order whatever the split: the step is the
// same, bit for bit, for any thread count.
TEST(LinearSolvers, SchurStepIsTheSameForAnyThreadCount) {
  ToyOptions options;
  options.poses = 12;
  options.points = 80;
  options.sharedScale = true;
  options.randomInformation = true;
  const Graph graph = makeToyProblem(options);
  BlockSystem system(graph, /*schurOrdering=*/true);
  system.fill(1);
  system.setDiagonalShift(1e-3 * system.diagonal());
  const Eigen::VectorXd rhs = -system.gradient();
  for (const char* name : {"schur_dense", "schur_cholmod"}) {
    Eigen::VectorXd oneThread;
    for (int threads : {1, 2, 3, 5}) {
      std::unique_ptr<LinearSolver> solver = Registry<LinearSolver>::instance().create(name);
      solver->analyze(system);
      Eigen::VectorXd x;
      ASSERT_TRUE(solver->solve(system, rhs, x, threads)) << name;
      if (threads == 1)
        oneThread = x;
      else
        EXPECT_EQ(x, oneThread) << name << ", " << threads << " threads";
    }
  }
}

// A vertex shared by every pose makes the reduced system an arrowhead: a
// block per pair of co-visible poses, one per pose with the shared vertex,
// and nothing between poses that see no common point.
TEST(LinearSolvers, SchurKeepsTheSharedVertexAnArrowhead) {
  ToyOptions options;
  options.poses = 8;
  options.points = 60;
  options.posesPerPoint = 3;
  options.sharedScale = true;
  options.fixedPoses = 1;
  options.fixedPoints = 4;
  Graph graph = makeToyProblem(options);

  std::set<std::pair<int, int>> covisible;  // free pose ids sharing a free (marginalised) point
  std::set<int> posesOnTheScale;
  std::map<int, std::set<int>> observers;
  for (const auto& edge : graph.edges()) {
    const Vertex* pose = edge->vertex(0);
    const Vertex* point = edge->vertex(1);
    if (pose->fixed()) continue;
    posesOnTheScale.insert(pose->id());
    if (!point->fixed()) observers[point->id()].insert(pose->id());
  }
  for (const auto& [point, poses] : observers)
    for (int a : poses)
      for (int b : poses)
        if (a < b) covisible.emplace(a, b);
  const int freePoses = options.poses - options.fixedPoses;
  const int expected = (freePoses + 1) + static_cast<int>(covisible.size()) + static_cast<int>(posesOnTheScale.size());
  ASSERT_LT(static_cast<int>(covisible.size()), freePoses * (freePoses - 1) / 2) << "every pair co-visible";

  BlockSystem system(graph, true);
  ASSERT_EQ(system.freeCount(), freePoses + 1);
  for (const char* name : {"schur_dense", "schur_cholmod"}) {
    std::unique_ptr<LinearSolver> solver = Registry<LinearSolver>::instance().create(name);
    auto* schur = dynamic_cast<SchurSolver*>(solver.get());
    ASSERT_NE(schur, nullptr) << name;
    schur->analyze(system);
    EXPECT_EQ(schur->reducedBlockCount(), expected) << name;
  }
}

// A negative shift makes H indefinite: every direct solver must say so, then
// recover on the next, positive definite, system of the same structure.
TEST(LinearSolvers, IndefiniteSystemIsReportedAndRecoveredFrom) {
  ToyOptions options;
  options.sharedScale = true;
  Graph graph = makeToyProblem(options);
  BlockSystem system(graph, true);
  system.fill(1);
  const Eigen::VectorXd rhs = -system.gradient();
  for (const std::string& name : registeredSolvers()) {
    std::unique_ptr<LinearSolver> solver = Registry<LinearSolver>::instance().create(name);
    if (!solver->exactSteps()) continue;
    solver->analyze(system);
    Eigen::VectorXd x;
    system.setDiagonalShift(-2.0 * system.diagonal());
    EXPECT_FALSE(solver->solve(system, rhs, x, 1)) << name;
    system.setDiagonalShift(1e-3 * system.diagonal());
    ASSERT_TRUE(solver->solve(system, rhs, x, 1)) << name;
    const Eigen::VectorXd reference = denseHessian(system).llt().solve(rhs);
    EXPECT_LE((x - reference).norm(), 1e-9 * reference.norm()) << name;
  }
}

// A residual that sees only the first coordinate of a point: its Hessian
// block diag(1, 0, 0) is exactly singular.
class EdgeFirstCoordinate : public BaseEdge<1, VertexPoint3> {
 public:
  static constexpr const char* kTypeTag = "TEST_FIRST_COORDINATE";
  const char* typeTag() const override { return kTypeTag; }
  void computeResidual(Residual& residual) const override {
    residual[0] = vertexAs<0>()->estimate().x() - measurement_[0];
  }
};

Graph makeSingularGraph(bool marginalised) {
  Graph graph;
  auto* point = graph.addVertex(std::make_unique<VertexPoint3>(0, Eigen::Vector3d(1.0, 2.0, 3.0)));
  point->setMarginalized(marginalised);
  auto edge = std::make_unique<EdgeFirstCoordinate>();
  edge->setVertex(0, point);
  edge->setMeasurement(Eigen::Matrix<double, 1, 1>(0.5));
  graph.addEdge(std::move(edge));
  return graph;
}

TEST(LinearSolvers, SingularSystemMakesSolveReturnFalse) {
  for (bool marginalised : {false, true}) {
    Graph graph = makeSingularGraph(marginalised);
    for (const std::string& name : registeredSolvers()) {
      std::unique_ptr<LinearSolver> solver = Registry<LinearSolver>::instance().create(name);
      BlockSystem system(graph, solver->usesSchurOrdering());
      system.fill(1);
      system.setDiagonalShift(Eigen::VectorXd::Zero(3));
      solver->analyze(system);
      Eigen::VectorXd x;
      EXPECT_FALSE(solver->solve(system, -system.gradient(), x, 1)) << name << (marginalised ? ", marginalised" : "");
    }
  }
}

TEST(LinearSolvers, GaussNewtonStopsOnASingularSystem) {
  for (bool marginalised : {false, true}) {
    for (const std::string& name : registeredSolvers()) {
      Graph graph = makeSingularGraph(marginalised);
      SolverOptions options;
      options.algorithm = "gn";
      options.linearSolver = name;
      const SolverSummary summary = Optimizer(options).optimize(graph);
      EXPECT_EQ(summary.termination, Termination::kSingularSystem) << name;
      EXPECT_EQ(summary.finalCost, summary.initialCost) << name;
      EXPECT_FALSE(summary.converged()) << name;
    }
  }
}

// LM's damping makes the same singular problem solvable: x moves to 0.5.
TEST(LinearSolvers, LevenbergMarquardtSolvesThroughASingularSystem) {
  for (const std::string& name : registeredSolvers()) {
    Graph graph = makeSingularGraph(false);
    SolverOptions options;
    options.linearSolver = name;
    const SolverSummary summary = Optimizer(options).optimize(graph);
    EXPECT_TRUE(summary.converged()) << name << ": " << summary.briefReport();
    EXPECT_NEAR(static_cast<VertexPoint3*>(graph.vertex(0))->estimate().x(), 0.5, 1e-6) << name;
  }
}

// Nothing fixed: the 7-dof gauge leaves H singular up to rounding. Gauss-
// Newton must either say so or end cleanly, never crash or raise the cost.
TEST(LinearSolvers, GaussNewtonWithAFreeGaugeEndsCleanly) {
  for (const std::string& name : registeredSolvers()) {
    ToyOptions problem;
    problem.fixedPoses = 0;
    Graph graph = makeToyProblem(problem);
    SolverOptions options;
    options.algorithm = "gn";
    options.linearSolver = name;
    options.maxIterations = 20;
    SolverSummary summary;
    ASSERT_NO_THROW(summary = Optimizer(options).optimize(graph)) << name;
    EXPECT_TRUE(std::isfinite(summary.finalCost)) << name;
    EXPECT_LE(summary.finalCost, summary.initialCost) << name;
    EXPECT_NEAR(graph.cost(), summary.finalCost, 1e-9 * summary.initialCost) << name;
  }
}

}  // namespace
}  // namespace lrsvo::test
