#include "apps/bench/ceres_nist.h"

#include <algorithm>

#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/problem.h>

#include "apps/bench/ceres_solve.h"
#include "lrsvo/eval/nist_models.h"

namespace lrsvo::bench {
namespace {

// r = y - f(b; x), one observation, b one parameter block.
struct NistObservationResidual {
  NistModel model;
  double response;
  double predictors[2];

  template <typename T>
  bool operator()(T const* const* parameters, T* residual) const {
    residual[0] = response - nistPrediction<T>(model, parameters[0], predictors);
    return true;
  }
};

}  // namespace

CeresNistSolve solveNistWithCeres(const NistProblem& problem, int start, const SolverOptions& stopping) {
  const NistModel model = nistModelOf(problem.name);
  CeresNistSolve solve;
  solve.estimate = problem.starts[start - 1];
  ceres::Problem ceresProblem;
  for (int i = 0; i < problem.observationCount(); ++i) {
    auto* residual = new NistObservationResidual{model, nistResponse(model, problem.response[i]), {0.0, 0.0}};
    for (int p = 0; p < std::min<int>(2, static_cast<int>(problem.predictors.cols())); ++p)
      residual->predictors[p] = problem.predictors(i, p);
    // Stride 10: every NIST model has at most 9 parameters, so one pass of Jets covers them all.
    auto* cost = new ceres::DynamicAutoDiffCostFunction<NistObservationResidual, 10>(residual);
    cost->AddParameterBlock(problem.parameterCount());
    cost->SetNumResiduals(1);
    ceresProblem.AddResidualBlock(cost, nullptr, solve.estimate.data());
  }
  solve.result = solveWithCeres(ceresSolverOptions(stopping, ceres::DENSE_QR), ceresProblem);
  return solve;
}

}  // namespace lrsvo::bench
