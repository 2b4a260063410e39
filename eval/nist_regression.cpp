#include "lrsvo/eval/nist_regression.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <type_traits>

#include "lrsvo/eval/nist_models.h"
#include "lrsvo/graph/autodiff_edge.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/optimizer.h"

namespace lrsvo {
namespace {

// A dual number with 9 derivatives, the most parameters of a model.
using NistDual = Dual<9>;

// The regression's parameters b, updated additively.
template <int N>
class VertexRegressionParameters : public VectorVertex<N> {
 public:
  using VectorVertex<N>::VectorVertex;
  const char* typeTag() const override { return "REGRESSION_PARAMETERS"; }
  std::unique_ptr<Vertex> clone() const override { return std::make_unique<VertexRegressionParameters>(*this); }
};

// One observation: r = y - f(b; x) (log y for Nelson), NIST's own residual.
template <int N>
class EdgeRegressionObservation : public AutoDiffEdge<EdgeRegressionObservation<N>, 1, VertexRegressionParameters<N>> {
 public:
  EdgeRegressionObservation(NistModel model, double response, const double* predictors, const NistSolveOptions& options)
      : model_(model), response_(response), jacobians_(options.jacobians), numeric_(options.numeric) {
    std::copy(predictors, predictors + 2, predictors_);
  }

  const char* typeTag() const override { return "REGRESSION_OBSERVATION"; }

  template <typename T>
  void residual(const Eigen::Matrix<T, N, 1>& b, Eigen::Matrix<T, 1, 1>& r) const {
    if constexpr (std::is_same_v<T, double>) {
      r[0] = response_ - nistPrediction(model_, b.data(), predictors_);
    } else {
      // The models are evaluated on one dual type for every parameter count,
      // so their 27 formulas compile once rather than once per count.
      std::array<NistDual, N> parameters;
      for (int k = 0; k < N; ++k) {
        parameters[k] = NistDual(b[k].value());
        parameters[k].v.template head<N>() = b[k].derivatives();
      }
      const NistDual prediction = nistPrediction(model_, parameters.data(), predictors_);
      r[0] = T(response_ - prediction.value(), -prediction.derivatives().template head<N>());
    }
  }

  void computeJacobians() override {
    if (jacobians_ == RegressionJacobians::kAutoDiff)
      this->computeAutoDiffJacobians();
    else
      this->computeNumericJacobians();
  }
  NumericDiffOptions numericDiffOptions() const override { return numeric_; }

 private:
  NistModel model_;
  double response_;
  double predictors_[2] = {0.0, 0.0};
  RegressionJacobians jacobians_;
  NumericDiffOptions numeric_;
};

template <int N>
NistSolve solveWith(const NistProblem& problem, int start, const NistSolveOptions& options) {
  const NistModel model = nistModelOf(problem.name);
  Graph graph;
  auto* parameters = graph.addVertex(std::make_unique<VertexRegressionParameters<N>>(0));
  parameters->setEstimateVector(problem.starts[start - 1]);
  for (int i = 0; i < problem.observationCount(); ++i) {
    double predictors[2] = {0.0, 0.0};
    for (int p = 0; p < std::min<int>(2, static_cast<int>(problem.predictors.cols())); ++p)
      predictors[p] = problem.predictors(i, p);
    auto edge = std::make_unique<EdgeRegressionObservation<N>>(model, nistResponse(model, problem.response[i]),
                                                               predictors, options);
    edge->setVertex(0, parameters);
    graph.addEdge(std::move(edge));
  }
  NistSolve solve;
  solve.problem = problem.name;
  solve.start = start;
  solve.summary = Optimizer(options.solver).optimize(graph);
  solve.estimate = parameters->estimate();
  solve.residualSumOfSquares = 2.0 * solve.summary.finalCost;
  solve.digits = correctDigits(solve.estimate, problem.certified);
  return solve;
}

}  // namespace

SolverOptions nistSolverOptions() {
  SolverOptions options = SolverOptions::fromName("lm_dense");
  options.maxIterations = 1000;
  options.functionTolerance = std::numeric_limits<double>::epsilon();
  options.gradientTolerance = std::numeric_limits<double>::epsilon();
  options.parameterTolerance = std::numeric_limits<double>::epsilon();
  // The parameters' magnitudes span 1e-9 to 1e6 (MGH10 starts at b2 = 4e5):
  // the damping floor is kept in the Jacobi-scaled units, as Ceres' is.
  options.lm.jacobiScaledDiagonal = true;
  return options;
}

double correctDigits(double estimate, double certified) {
  constexpr double kCertifiedDigits = 11.0;
  if (!std::isfinite(estimate)) return 0.0;
  const double relative = std::abs(estimate - certified) / std::abs(certified);
  if (relative == 0.0) return kCertifiedDigits;
  if (relative >= 1.0) return 0.0;  // not -0.0, which -log10(1) would print as
  return std::min(-std::log10(relative), kCertifiedDigits);
}

Eigen::VectorXd correctDigits(const Eigen::VectorXd& estimate, const Eigen::VectorXd& certified) {
  Eigen::VectorXd digits(certified.size());
  for (Eigen::Index k = 0; k < certified.size(); ++k) digits[k] = correctDigits(estimate[k], certified[k]);
  return digits;
}

std::vector<std::string> nistProblemFiles(const std::string& directory) {
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.path().extension() == ".dat") files.push_back(entry.path().string());
  if (error) throw Error("cannot read the NIST folder '" + directory + "': " + error.message());
  if (files.empty()) throw Error("no NIST problem files (*.dat) in '" + directory + "'");
  std::sort(files.begin(), files.end());
  return files;
}

NistSolve solveNist(const NistProblem& problem, int start, const NistSolveOptions& options) {
  if (start != 1 && start != 2) throw Error("a NIST problem has starts 1 and 2, not " + std::to_string(start));
  switch (problem.parameterCount()) {
    case 2: return solveWith<2>(problem, start, options);
    case 3: return solveWith<3>(problem, start, options);
    case 4: return solveWith<4>(problem, start, options);
    case 5: return solveWith<5>(problem, start, options);
    case 6: return solveWith<6>(problem, start, options);
    case 7: return solveWith<7>(problem, start, options);
    case 8: return solveWith<8>(problem, start, options);
    case 9: return solveWith<9>(problem, start, options);
    default:
      throw Error("NIST problem " + problem.name + " has " + std::to_string(problem.parameterCount()) +
                  " parameters; the models have 2 to 9");
  }
}

}  // namespace lrsvo
