#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <nlopt.hpp>

#include "lrsvo/constraints/builtin_methods.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {
namespace {

// Bound-constrained minimisation of the same graph by an NLopt algorithm,
// with the graph's analytic gradient: a reference for small graphs and a
// test oracle. NLopt sees the update dx of every active vertex around an
// anchor; for non-Euclidean vertices (poses) the gradient is exact only at
// dx = 0, so each round re-anchors at its result until a round stops
// improving the cost.
class NloptMethod : public ConstraintMethod {
 public:
  NloptMethod(nlopt::algorithm algorithm, std::string name) : algorithm_(algorithm), name_(std::move(name)) {
    declare("evaluations", &maxEvaluations_, "NLopt's evaluations per round");
    declare("rounds", &maxRounds_, "rounds at most, each re-anchoring the tangent space at the last one's result");
  }

  SolverSummary solve(Graph& graph, const SolverOptions& options) override {
    const Stopwatch start;
    enforceStart(false);
    BlockSystem system(graph, false);
    SolverSummary summary = beginSummary(name_, graph, system, options.threads);
    if (!std::isfinite(summary.initialCost)) throw Error("nlopt: the start cost is not finite");
    summary.iterations.push_back({.iteration = 0, .cost = summary.initialCost});

    Objective objective{system, options.threads, 0};
    double cost = summary.initialCost;
    summary.termination = Termination::kMaxIterations;
    for (int round = 1; round <= maxRounds_; ++round) {
      system.saveEstimates();
      nlopt::opt optimizer(algorithm_, static_cast<unsigned>(system.scalarCount()));
      std::vector<double> lower, upper;
      boxAroundAnchor(system, lower, upper);
      optimizer.set_lower_bounds(lower);
      optimizer.set_upper_bounds(upper);
      optimizer.set_min_objective(&Objective::evaluate, &objective);
      optimizer.set_ftol_rel(options.functionTolerance);
      optimizer.set_xtol_rel(options.parameterTolerance);
      optimizer.set_maxeval(maxEvaluations_);
      std::vector<double> dx(system.scalarCount(), 0.0);
      double roundCost = cost;
      try {
        optimizer.optimize(dx, roundCost);
      } catch (const nlopt::roundoff_limited&) {
        // NLopt stops at the precision limit and keeps its best point.
      } catch (const std::exception& e) {
        summary.message = std::string("nlopt: ") + e.what();
      }
      system.restoreEstimates();
      system.applyStep(Eigen::Map<const Eigen::VectorXd>(dx.data(), dx.size()));
      roundCost = system.cost(options.threads);
      const double decrease = cost - roundCost;
      if (!(decrease >= 0.0)) {  // never keep a worse point
        system.restoreEstimates();
        summary.termination = Termination::kNoDescent;
        break;
      }
      cost = roundCost;
      summary.iterations.push_back({.iteration = round,
                                    .cost = cost,
                                    .costChange = decrease,
                                    .stepNorm = Eigen::Map<const Eigen::VectorXd>(dx.data(), dx.size()).norm(),
                                    .accepted = true,
                                    .cumulativeSeconds = start.seconds()});
      ++summary.successfulSteps;
      if (decrease <= options.functionTolerance * cost) {
        summary.termination = Termination::kFunctionTolerance;
        break;
      }
    }
    summary.finalCost = cost;
    summary.linearizeSeconds = objective.seconds;
    summary.totalSeconds = start.seconds();
    summary.message += (summary.message.empty() ? "" : "; ") + std::to_string(objective.evaluations) + " evaluations";
    return summary;
  }

 private:
  struct Objective {
    BlockSystem& system;
    int threads;
    int evaluations;
    double seconds = 0.0;

    static double evaluate(const std::vector<double>& dx, std::vector<double>& gradient, void* data) {
      auto& self = *static_cast<Objective*>(data);
      const Stopwatch start;
      ++self.evaluations;
      self.system.restoreEstimates();
      self.system.applyStep(Eigen::Map<const Eigen::VectorXd>(dx.data(), dx.size()));
      double cost = self.system.fill(self.threads);
      if (!gradient.empty()) Eigen::Map<Eigen::VectorXd>(gradient.data(), gradient.size()) = self.system.gradient();
      self.seconds += start.seconds();
      return std::isfinite(cost) ? cost : std::numeric_limits<double>::max();
    }
  };

  // Bounds on dx: x0 + dx within [lower, upper] for bounded parameters.
  void boxAroundAnchor(const BlockSystem& system, std::vector<double>& lower, std::vector<double>& upper) const {
    lower.assign(system.scalarCount(), -HUGE_VAL);
    upper.assign(system.scalarCount(), HUGE_VAL);
    for (const Bounds::Bound& bound : bounds_.all()) {
      const int block = system.blockOf(bound.vertex);
      if (block < 0) continue;
      const double x = Bounds::value(bound);
      lower[system.offset(block) + bound.index] = std::min(0.0, bound.lower - x);
      upper[system.offset(block) + bound.index] = std::max(0.0, bound.upper - x);
    }
  }

  nlopt::algorithm algorithm_;
  std::string name_;
  int maxEvaluations_ = 5000;
  int maxRounds_ = 20;
};

void addNlopt(Registry<ConstraintMethod>& registry, const char* name, nlopt::algorithm algorithm,
              const char* description) {
  registry.add(
      name, [=] { return std::make_unique<NloptMethod>(algorithm, name); }, description);
}

}  // namespace

void addNloptMethods(Registry<ConstraintMethod>& registry) {
  addNlopt(registry, "nlopt_lbfgs", nlopt::LD_LBFGS,
           "NLopt L-BFGS with bounds on the graph's analytic gradient (small graphs, test oracle)");
  addNlopt(registry, "nlopt_mma", nlopt::LD_MMA, "NLopt MMA (method of moving asymptotes) with bounds");
}
}  // namespace lrsvo
