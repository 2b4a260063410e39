#include "lrsvo/graph/optimization_algorithm.h"

namespace lrsvo {

SolverSummary beginSummary(const std::string& solverName, const Graph& graph, const BlockSystem& system, int threads) {
  SolverSummary summary;
  summary.solver = solverName;
  summary.threads = threads;
  summary.vertexCount = system.blockCount();
  summary.edgeCount = static_cast<int>(graph.edges().size());
  summary.parameterCount = system.scalarCount();
  summary.initialCost = system.cost(threads);
  return summary;
}

void OptimizationAlgorithm::run(OptimizationContext& context) {
  const SolverOptions& options = context.options();
  SolverSummary& summary = context.summary();
  BlockSystem& system = context.system();

  double cost = context.linearize();
  summary.iterations.front().gradientMaxNorm = context.constraints().gradientMaxNorm(system);
  begin(context);

  for (int iteration = 1;; ++iteration) {
    const double gradientNorm = context.constraints().gradientMaxNorm(system);
    if (gradientNorm <= options.gradientTolerance) {
      summary.termination = Termination::kGradientTolerance;
      break;
    }
    if (iteration > options.maxIterations) {
      summary.termination = Termination::kMaxIterations;
      break;
    }
    if (context.outOfTime()) {
      summary.termination = Termination::kTimeLimit;
      break;
    }

    IterationRecord record{.iteration = iteration, .cost = cost, .gradientMaxNorm = gradientNorm};
    double trialCost = cost;
    const Step step = tryStep(context, cost, record, trialCost);
    if (step == Step::kStop) break;
    if (step == Step::kAccepted) {
      const double relativeDecrease = (cost - trialCost) / cost;
      cost = trialCost;
      record.cost = cost;
      record.accepted = true;
      ++summary.successfulSteps;
      if (relativeDecrease <= options.functionTolerance) {
        context.record(record);
        summary.termination = Termination::kFunctionTolerance;
        break;
      }
      cost = context.linearize();
    } else {
      ++summary.unsuccessfulSteps;
      afterRejection();
    }
    context.record(record);
    if (exhausted(summary)) break;
  }
  summary.finalCost = cost;
}

}  // namespace lrsvo
