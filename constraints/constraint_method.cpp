#include "lrsvo/constraints/constraint_method.h"

#include <algorithm>
#include <string>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

void ConstraintMethod::begin(Graph&) { enforceStart(needsInteriorStart()); }

bool ConstraintMethod::limitBoundedSteps(const BlockSystem& system, Eigen::VectorXd& dx, const StepLimit& limit) const {
  bool changed = false;
  for (const Bounds::Bound& bound : bounds_.all()) {
    const int block = system.blockOf(bound.vertex);
    if (block < 0) continue;
    double& step = dx[system.offset(block) + bound.index];
    const double limited = limit(bound, Bounds::value(bound), step);
    if (limited != step) {
      step = limited;
      changed = true;
    }
  }
  return changed;
}

void ConstraintMethod::enforceStart(bool interior) const {
  for (const Bounds::Bound& bound : bounds_.all()) {
    const double x = Bounds::value(bound);
    const double margin = interior ? settings_.interiorMargin * bound.halfWidth() : 0.0;
    const double lower = bound.lower + margin, upper = bound.upper - margin;
    if (x >= lower && x <= upper && (!interior || (x > bound.lower && x < bound.upper))) continue;
    if (settings_.start == StartPolicy::kError)
      throw Error("start outside the bounds: vertex " + std::to_string(bound.vertex->id()) + " (" +
                  bound.vertex->typeTag() + ") parameter " + std::to_string(bound.index) + " = " + std::to_string(x) +
                  (interior ? " is not strictly inside [" : " is outside [") + std::to_string(bound.lower) + ", " +
                  std::to_string(bound.upper) + "]; fix the start or set the start policy to project");
    Bounds::setValue(bound, std::clamp(x, lower, upper));
  }
}

SolverSummary ConstraintMethod::solve(Graph& graph, const SolverOptions& options) {
  Optimizer optimizer(options);
  const double initialCost = graph.cost(options.threads);
  SolverSummary summary = optimizer.optimize(graph, *this);
  summary.initialCost = initialCost;
  summary.finalCost = graph.cost(options.threads);
  return summary;
}

SolverSummary optimizeWithBounds(Graph& graph, const SolverOptions& options, const Bounds& bounds,
                                 const std::string& specification, const ConstraintSettings& settings) {
  std::unique_ptr<ConstraintMethod> constraints = makeConstraintMethod(specification);
  constraints->setBounds(bounds);
  constraints->setSettings(settings);
  return constraints->solve(graph, options);
}

void appendSummary(SolverSummary& total, const SolverSummary& part) {
  const double offset = total.iterations.empty() ? 0.0 : total.iterations.back().cumulativeSeconds;
  const int first = total.iterationCount();
  for (std::size_t k = 1; k < part.iterations.size(); ++k) {
    IterationRecord record = part.iterations[k];
    record.iteration = first + static_cast<int>(k);
    record.cumulativeSeconds += offset;
    total.iterations.push_back(record);
  }
  total.finalCost = part.finalCost;
  total.successfulSteps += part.successfulSteps;
  total.unsuccessfulSteps += part.unsuccessfulSteps;
  total.termination = part.termination;
  total.message = part.message;
  total.setupSeconds += part.setupSeconds;
  total.linearizeSeconds += part.linearizeSeconds;
  total.schurSeconds += part.schurSeconds;
  total.factorizeSeconds += part.factorizeSeconds;
  total.costSeconds += part.costSeconds;
  total.totalSeconds += part.totalSeconds;
}

}  // namespace lrsvo
