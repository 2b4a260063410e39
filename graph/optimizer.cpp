#include "lrsvo/graph/optimizer.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

namespace {

void checkEstimatesFinite(const Graph& graph) {
  std::vector<double> values;
  for (const auto& v : graph.vertices()) {
    values.resize(v->estimateSize());
    v->getEstimate(values.data());
    for (double x : values)
      if (!std::isfinite(x))
        throw Error(std::string("vertex ") + std::to_string(v->id()) + " (" + v->typeTag() +
                    ") has a non-finite estimate");
  }
}

[[noreturn]] void throwNonFiniteCost(const Graph& graph) {
  for (const auto& edge : graph.edges()) {
    if (std::isfinite(edge->cost())) continue;
    std::string ids;
    for (const Vertex* v : edge->vertices()) ids.append(" ").append(std::to_string(v->id()));
    throw Error(std::string("the start cost is not finite: edge ") + edge->typeTag() + " on vertices" + ids +
                " gives " + std::to_string(edge->cost()));
  }
  throw Error("the start cost is not finite");
}

// Calls ConstraintHandler::end however the solve leaves.
struct ConstraintScope {
  ConstraintHandler& handler;
  Graph& graph;
  ConstraintScope(ConstraintHandler& h, Graph& g) : handler(h), graph(g) { handler.begin(graph); }
  ~ConstraintScope() { handler.end(graph); }
  ConstraintScope(const ConstraintScope&) = delete;
  ConstraintScope& operator=(const ConstraintScope&) = delete;
};

}  // namespace

Damping dampingFromName(const std::string& name) {
  if (name == "multiplicative") return Damping::kMultiplicative;
  if (name == "additive") return Damping::kAdditive;
  throw Error("damping must be 'multiplicative' or 'additive', got '" + name + "'");
}

SolverOptions SolverOptions::fromName(const std::string& name) {
  SolverOptions options;
  const auto split = name.find('_');
  if (split == std::string::npos) throw Error("solver name '" + name + "' is not <algorithm>_<linear solver>");
  options.algorithm = name.substr(0, split);
  options.linearSolver = name.substr(split + 1);
  options.validate();
  return options;
}

void SolverOptions::setName(const std::string& name) {
  const SolverOptions named = fromName(name);
  algorithm = named.algorithm;
  linearSolver = named.linearSolver;
}

void SolverOptions::validate() const {
  if (!Registry<OptimizationAlgorithm>::instance().contains(algorithm))
    Registry<OptimizationAlgorithm>::instance().create(algorithm);  // throws, listing known names
  if (!Registry<LinearSolver>::instance().contains(linearSolver))
    Registry<LinearSolver>::instance().create(linearSolver);
  if (threads < 1) throw Error("solver: threads must be at least 1");
  if (maxIterations < 0) throw Error("solver: max iterations must not be negative");
}

// The block system of the last solve and the linear solver that analysed it.
struct Optimizer::Prepared {
  std::unique_ptr<LinearSolver> solver;
  std::unique_ptr<BlockSystem> system;
};

Optimizer::Optimizer(SolverOptions options) : options_(std::move(options)) { options_.validate(); }
Optimizer::~Optimizer() = default;
Optimizer::Optimizer(const Optimizer& other) : options_(other.options_) {}
Optimizer& Optimizer::operator=(const Optimizer& other) {
  if (this != &other) {
    options_ = other.options_;
    prepared_.reset();
  }
  return *this;
}
Optimizer::Optimizer(Optimizer&&) noexcept = default;
Optimizer& Optimizer::operator=(Optimizer&&) noexcept = default;

void Optimizer::releaseStructure() { prepared_.reset(); }

SolverSummary Optimizer::optimize(Graph& graph) {
  ConstraintHandler unconstrained;
  return optimize(graph, unconstrained);
}

SolverSummary Optimizer::optimize(Graph& graph, ConstraintHandler& constraints) {
  const Stopwatch start;
  if (graph.empty()) throw Error("optimise: the graph has no vertices");
  checkEstimatesFinite(graph);
  auto algorithm = Registry<OptimizationAlgorithm>::instance().create(options_.algorithm);

  ConstraintScope scope(constraints, graph);
  const bool reused = prepared_ && prepared_->system->describes(graph, prepared_->solver->usesSchurOrdering());
  if (!reused) {
    // The old structure goes first, so that the two are never held at once.
    prepared_.reset();
    auto solver = Registry<LinearSolver>::instance().create(options_.linearSolver);
    auto system = std::make_unique<BlockSystem>(graph, solver->usesSchurOrdering());
    solver->analyze(*system);
    prepared_ = std::make_unique<Prepared>(Prepared{std::move(solver), std::move(system)});
  }
  BlockSystem& system = *prepared_->system;
  LinearSolver& solver = *prepared_->solver;

  SolverSummary summary = beginSummary(options_.name(), graph, system, options_.threads);
  summary.structureReused = reused;
  const FactorizationInfo factorization = solver.factorization();
  summary.ordering = factorization.ordering;
  summary.factorizationFlops = factorization.flops;
  if (!std::isfinite(summary.initialCost)) throwNonFiniteCost(graph);
  summary.setupSeconds = start.seconds();

  OptimizationContext context(system, solver, constraints, options_, summary);
  context.record(IterationRecord{.iteration = 0, .cost = summary.initialCost, .lambda = 0.0});
  algorithm->run(context);
  summary.totalSeconds = start.seconds();
  return summary;
}

}  // namespace lrsvo
