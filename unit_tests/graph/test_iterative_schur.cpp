// The iterative Schur solvers (schur_pcg, schur_power_series): their steps
// against the dense solution within the bounds their stopping rules give,
// the same step for any thread count, what they refuse, and whole solves.
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/schur_pcg_solver.h"
#include "lrsvo/graph/schur_power_series_solver.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// The system's reduced quantities, formed densely: S = H_aa - H_ap H_pp^-1 H_pa,
// b = r_a - H_ap H_pp^-1 r_p, and the full step x* = H^-1 rhs.
struct DenseReference {
  Eigen::MatrixXd h, s;
  Eigen::VectorXd rhs, b, step;
};

DenseReference denseReference(const BlockSystem& system) {
  DenseReference d;
  d.h = denseHessian(system);
  d.rhs = -system.gradient();
  const int a = system.freeScalarCount(), p = system.scalarCount() - a;
  const Eigen::MatrixXd hap = d.h.topRightCorner(a, p);
  const Eigen::LLT<Eigen::MatrixXd> hpp(d.h.bottomRightCorner(p, p));
  d.s = d.h.topLeftCorner(a, a) - hap * hpp.solve(hap.transpose());
  d.b = d.rhs.head(a) - hap * hpp.solve(d.rhs.tail(p));
  d.step = d.h.llt().solve(d.rhs);
  return d;
}

double smallestEigenvalue(const Eigen::MatrixXd& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues().minCoeff();
}

// The system refers to the graph's vertices and edges: the graph must outlive it.
BlockSystem filledSystem(const Graph& graph, double relativeShift) {
  BlockSystem system(graph, /*schurOrdering=*/true);
  system.fill(1);
  system.setDiagonalShift(relativeShift * system.diagonal());
  return system;
}

Graph balProblem(std::uint64_t seed) {
  BalToyOptions options;
  options.cameras = 6;
  options.points = 60;
  options.fixedCameras = 2;  // and with them the scale: H is definite without damping
  options.randomInformation = true;
  options.seed = seed;
  return makeBalToyProblem(options);
}

Graph posesWithASharedScale(std::uint64_t seed) {
  ToyOptions options;
  options.poses = 8;
  options.points = 60;
  options.sharedScale = true;
  options.randomInformation = true;
  options.seed = seed;
  return makeToyProblem(options);
}

// CG stops once its recursive residual is below tol |b|. The true residual of
// the full system is then (S xa - b, 0) up to rounding, which drifts from
// the recursive one by at most about iterations * eps * |S| |xa| (Greenbaum's
// bound, with a factor 10 for the constants); and |x - x*| <= |H x - rhs| /
// lambda_min(H).
void expectConjugateGradientsWithinTheirBound(const Graph& graph) {
  const BlockSystem system = filledSystem(graph, 1e-3);
  const DenseReference d = denseReference(system);
  ConjugateGradientOptions options;
  options.eta = 0.0;
  options.residualTolerance = 1e-12;
  options.maxIterations = 100 * system.freeScalarCount();
  SchurPcgSolver solver(options);
  solver.analyze(system);
  Eigen::VectorXd x;
  ASSERT_TRUE(solver.solve(system, d.rhs, x, 1));
  ASSERT_LT(solver.lastIterations(), options.maxIterations) << "stopped by the cap, not the tolerance";
  const double drift = 10.0 * solver.lastIterations() * kEpsilon * d.s.norm() * x.head(d.b.size()).norm();
  const double residual = (d.h * x - d.rhs).norm();
  EXPECT_LE(residual, options.residualTolerance * d.b.norm() + drift + 10.0 * kEpsilon * d.h.norm() * x.norm());
  EXPECT_LE((x - d.step).norm(), residual / smallestEigenvalue(d.h) * (1.0 + 1e-6));
}

TEST(IterativeSchur, ConjugateGradientsReachTheDenseStepWithinTheirBound) {
  for (std::uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectConjugateGradientsWithinTheirBound(balProblem(seed));
    expectConjugateGradientsWithinTheirBound(posesWithASharedScale(seed));
  }
}

// With D the block diagonal of U and T = I - D^-1 S = D^-1 (D - S), the sum
// of the first N terms misses T^N (I - T)^-1 t_0, t_0 = D^-1 b. T is
// self-adjoint in the D inner product with eigenvalues in [0, rho], rho < 1,
// so that rest has D-norm at most rho^N / (1 - rho) |t_0|_D, and 2-norm at
// most rho^N / (1 - rho) sqrt(cond D) |t_0|. Rounding adds about eps |xa| per
// term, carried through the contraction: N eps sqrt(cond D) |xa| / (1 - rho).
TEST(IterativeSchur, PowerSeriesReachesTheDenseStepWithinItsTruncationBound) {
  for (std::uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Graph graph = balProblem(seed);
    const BlockSystem system = filledSystem(graph, 1e-3);
    const DenseReference d = denseReference(system);
    const int a = system.freeScalarCount();
    Eigen::MatrixXd blockDiagonal = Eigen::MatrixXd::Zero(a, a);
    for (int i = 0; i < system.freeCount(); ++i)
      blockDiagonal.block(system.offset(i), system.offset(i), system.dim(i), system.dim(i)) =
          d.h.block(system.offset(i), system.offset(i), system.dim(i), system.dim(i));
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> contraction(blockDiagonal - d.s, blockDiagonal);
    const double rho = contraction.eigenvalues().cwiseAbs().maxCoeff();
    ASSERT_GE(contraction.eigenvalues().minCoeff(), -1e-12);
    ASSERT_LT(rho, 1.0) << "the series would not converge";
    const Eigen::VectorXd diagonalEigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(blockDiagonal).eigenvalues();
    const double conditionOfD = diagonalEigenvalues.maxCoeff() / diagonalEigenvalues.minCoeff();
    const double firstTerm = blockDiagonal.llt().solve(d.b).norm();

    PowerSeriesOptions options;
    options.tolerance = 0.0;
    options.maxTerms = static_cast<int>(std::ceil(std::log(1e-10) / std::log(rho)));
    ASSERT_LE(options.maxTerms, 100000) << "rho = " << rho;
    SchurPowerSeriesSolver solver(options);
    solver.analyze(system);
    Eigen::VectorXd x;
    ASSERT_TRUE(solver.solve(system, d.rhs, x, 1));
    EXPECT_EQ(solver.lastTerms(), options.maxTerms);
    const double xaNorm = x.head(a).norm();
    const double truncation = std::pow(rho, options.maxTerms) / (1.0 - rho) * std::sqrt(conditionOfD) * firstTerm;
    const double rounding = 10.0 * options.maxTerms * kEpsilon * std::sqrt(conditionOfD) * xaNorm / (1.0 - rho);
    EXPECT_LE((x.head(a) - d.step.head(a)).norm(), truncation + rounding);
    // The marginalised part follows from the free part by back-substitution:
    // its rows of H x = rhs hold up to the rounding of one product.
    EXPECT_LE((d.h * x - d.rhs).tail(system.scalarCount() - a).norm(),
              10.0 * kEpsilon * (d.h.norm() * x.norm() + d.rhs.norm()));
  }
}

// Each marginalised vertex's sums, each chunk's and each row's run in a fixed
// order whatever the split among threads: the steps are the same, bit for bit.
TEST(IterativeSchur, StepsAreTheSameForAnyThreadCount) {
  const Graph graph = balProblem(4);
  const BlockSystem system = filledSystem(graph, 1e-3);
  const Eigen::VectorXd rhs = -system.gradient();
  for (const std::string name : {"pcg", "power series"}) {
    Eigen::VectorXd oneThread;
    for (int threads : {1, 2, 3, 5}) {
      std::unique_ptr<LinearSolver> solver;
      if (name == "pcg")
        solver = std::make_unique<SchurPcgSolver>();
      else
        solver = std::make_unique<SchurPowerSeriesSolver>();
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

TEST(IterativeSchur, PowerSeriesRefusesFreeVerticesCoupledByAnEdge) {
  const Graph graph = posesWithASharedScale(1);
  const BlockSystem system = filledSystem(graph, 1e-3);
  SchurPowerSeriesSolver solver;
  try {
    solver.analyze(system);
    FAIL() << "analyze() accepted a shared free vertex";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("use schur_pcg"), std::string::npos) << error.what();
  }
}

TEST(IterativeSchur, IndefiniteSystemIsReportedAndRecoveredFrom) {
  const Graph graph = balProblem(1);
  BlockSystem system(graph, true);
  system.fill(1);
  const Eigen::VectorXd rhs = -system.gradient();
  SchurPcgSolver pcg;
  SchurPowerSeriesSolver series;
  for (LinearSolver* solver : {static_cast<LinearSolver*>(&pcg), static_cast<LinearSolver*>(&series)}) {
    solver->analyze(system);
    Eigen::VectorXd x;
    system.setDiagonalShift(-2.0 * system.diagonal());
    EXPECT_FALSE(solver->solve(system, rhs, x, 1));
    system.setDiagonalShift(1e-3 * system.diagonal());
    ASSERT_TRUE(solver->solve(system, rhs, x, 1));
    EXPECT_TRUE(x.allFinite());
    EXPECT_GT(-system.gradient().dot(x), 0.0) << "not a descent direction";
  }
}

// Levenberg-Marquardt with inexact steps reaches the minimum the direct
// solver reaches. With the function tolerance at 1e-14 both stop where a
// step changes the cost by less than that; at such a point the cost is
// within about the last decrease of the minimum, far inside 1e-9.
TEST(IterativeSchur, LevenbergMarquardtReachesTheDirectSolversMinimum) {
  for (std::uint64_t seed : {1, 2}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    double directCost = 0.0;
    for (const char* name : {"lm_schur_dense", "lm_schur_pcg", "lm_schur_power_series"}) {
      Graph graph = balProblem(seed);
      SolverOptions options = SolverOptions::fromName(name);
      options.functionTolerance = 1e-14;
      options.gradientTolerance = 1e-12;
      options.parameterTolerance = 1e-14;
      options.maxIterations = 200;
      const SolverSummary summary = Optimizer(options).optimize(graph);
      EXPECT_TRUE(summary.converged()) << name << ": " << terminationName(summary.termination);
      EXPECT_LT(summary.finalCost, summary.initialCost) << name;
      if (std::string(name) == "lm_schur_dense")
        directCost = summary.finalCost;
      else
        EXPECT_NEAR(summary.finalCost, directCost, 1e-9 * directCost) << name;
    }
  }
}

}  // namespace
}  // namespace lrsvo::test
