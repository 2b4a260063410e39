// Geodesic acceleration: the residuals' second directional derivative that
// BlockSystem sums, and Levenberg-Marquardt with the accelerated steps.

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/robust_kernel.h"
#include "unit_tests/graph/test_problems.h"

namespace lrsvo::test {
namespace {

class VertexPlane : public VectorVertex<2> {
 public:
  using VectorVertex<2>::VectorVertex;
  const char* typeTag() const override { return "TEST_PLANE"; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexPlane>(*this); }
};

// A residual quadratic in the parameters, r = (x0^2 + 3 x0 x1 - 1, x1^2 - 2):
// its second derivative along v is (2 v0^2 + 6 v0 v1, 2 v1^2) everywhere, and
// r(x + h v) = r + h J v + h^2 r'' / 2 holds exactly, so the finite difference
// returns r'' up to rounding whatever h.
class EdgeQuadraticResidual : public AutoDiffEdge<EdgeQuadraticResidual, 2, VertexPlane> {
 public:
  const char* typeTag() const override { return "TEST_QUADRATIC_RESIDUAL"; }
  template <typename T>
  void residual(const Eigen::Matrix<T, 2, 1>& x, Eigen::Matrix<T, 2, 1>& r) const {
    r << x[0] * x[0] + 3.0 * x[0] * x[1] - 1.0, x[1] * x[1] - 2.0;
  }
};

struct QuadraticGraph {
  Graph graph;
  VertexPlane* plane = nullptr;
  EdgeQuadraticResidual* edge = nullptr;
};

std::unique_ptr<QuadraticGraph> quadraticGraph(const std::string& kernel) {
  auto problem = std::make_unique<QuadraticGraph>();
  problem->plane = problem->graph.addVertex(std::make_unique<VertexPlane>(0));
  problem->plane->setEstimateVector(Eigen::Vector2d(1.3, -0.4));
  auto edge = std::make_unique<EdgeQuadraticResidual>();
  edge->setVertex(0, problem->plane);
  Eigen::Matrix2d information;
  information << 4.0, 1.0, 1.0, 2.0;
  edge->setInformation(information);
  if (!kernel.empty()) edge->setRobustKernel(makeRobustKernel(kernel, 0.5));
  problem->edge = problem->graph.addEdge(std::move(edge));
  return problem;
}

// sum_e J^T r'' for the quadratic residual, with the whitening L (L^T L = Omega)
// and the kernel's sqrt(rho') s folded into both factors as the blocks have them:
// (s L J)^T (s L r''). The finite difference's rounding is eps |r| / h^2 relative
// to r'' (r ~ 1, r'' ~ 1, h = 0.1: 2e-14); 1e-11 leaves room for the products.
TEST(GeodesicAcceleration, SecondDirectionalGradientOfAQuadraticResidualIsExact) {
  for (const char* kernel : {"", "Huber", "Cauchy"}) {
    std::unique_ptr<QuadraticGraph> problem = quadraticGraph(kernel);
    BlockSystem system(problem->graph, false);
    system.fill(1);
    const Eigen::Vector2d x = problem->plane->estimate();
    const Eigen::Vector2d v(0.7, -1.1);
    const double h = 0.1;
    const Eigen::VectorXd sum = system.secondDirectionalGradient(v, h);
    EXPECT_EQ(problem->plane->estimate(), x) << "the estimates are restored";

    Eigen::Matrix2d jacobian;
    jacobian << 2.0 * x[0] + 3.0 * x[1], 3.0 * x[0], 0.0, 2.0 * x[1];
    const Eigen::Vector2d second(2.0 * v[0] * v[0] + 6.0 * v[0] * v[1], 2.0 * v[1] * v[1]);
    const Eigen::Matrix2d root = problem->edge->information().llt().matrixU();
    Eigen::Vector2d r;
    problem->edge->computeResidual(r);
    double weight = 1.0;
    if (problem->edge->robustKernel()) problem->edge->robustKernel()->evaluate((root * r).squaredNorm(), &weight);
    const Eigen::Vector2d expected = weight * (root * jacobian).transpose() * (root * second);
    EXPECT_LT((sum - expected).norm(), 1e-11 * expected.norm())
        << "kernel '" << kernel << "': " << sum.transpose() << " against " << expected.transpose();
  }
}

TEST(GeodesicAcceleration, AHeldCoordinateIsNotAccelerated) {
  std::unique_ptr<QuadraticGraph> problem = quadraticGraph("");
  BlockSystem system(problem->graph, false);
  system.fill(1);
  system.holdCoordinate(0, 1);
  const Eigen::VectorXd sum = system.secondDirectionalGradient(Eigen::Vector2d(0.7, -1.1), 0.1);
  EXPECT_EQ(sum[1], 0.0);
  EXPECT_NE(sum[0], 0.0);
  system.fill(1);
  EXPECT_NE(system.secondDirectionalGradient(Eigen::Vector2d(0.7, -1.1), 0.1)[1], 0.0) << "fill() releases it";
}

// On the toy bundle adjustments (with and without robust kernels), accelerated
// steps keep the cost monotone and reach the minimum plain steps reach: both
// stop by the function tolerance 1e-10 relative, so their costs agree to that
// tolerance times the few dozen steps of the tail, 1e-8 relative.
TEST(GeodesicAcceleration, LevenbergMarquardtReachesThePlainMinimum) {
  for (std::uint64_t seed : {1, 2, 3}) {
    for (const char* kernel : {"", "Huber"}) {
      ToyOptions toy;
      toy.seed = seed;
      toy.poses = 6;
      toy.points = 50;
      toy.poseNoise = 0.05;
      toy.pointNoise = 0.3;
      toy.kernel = kernel;
      toy.kernelDelta = 10.0;
      SolverOptions options = SolverOptions::fromName("lm_schur_dense");
      options.functionTolerance = 1e-10;
      options.maxIterations = 200;
      Graph plainGraph = makeToyProblem(toy);
      const SolverSummary plain = Optimizer(options).optimize(plainGraph);
      options.lm.geodesicAcceleration = true;
      Graph acceleratedGraph = makeToyProblem(toy);
      const SolverSummary accelerated = Optimizer(options).optimize(acceleratedGraph);
      for (std::size_t k = 1; k < accelerated.iterations.size(); ++k)
        EXPECT_LE(accelerated.iterations[k].cost, accelerated.iterations[k - 1].cost);
      EXPECT_NEAR(accelerated.finalCost, plain.finalCost, 1e-8 * plain.finalCost)
          << "seed " << seed << " kernel '" << kernel << "': " << accelerated.briefReport();
    }
  }
}

}  // namespace
}  // namespace lrsvo::test
