#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "lrsvo/constraints/barrier_edge.h"
#include "lrsvo/constraints/builtin_methods.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/optimizer.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// The paper's method: one unary barrier edge per bounded parameter, solved
// by the ordinary optimiser. mu shrinks over outer rounds, an interior-point
// schedule; one round keeps mu fixed. A trial step that would take a bounded
// parameter out of the box, or onto its bound, goes only a fraction
// (`boundary_fraction`) of the way from the parameter to that bound, as
// interior-point methods keep their iterates inside. Tried whole, such a
// step would cost +inf and be rejected; the damping would then grow until
// the step fits inside, and shrink every other parameter's step with it, so
// a parameter the data push against a bound (a weakly observed centre
// coordinate, an angle that trades off against the scale) would hold the
// whole adjustment to short steps. boundary_fraction = 1 tries every step
// whole, the plain barrier, for comparison.
class LogBarrier : public ConstraintMethod {
 public:
  LogBarrier() {
    declare("mu", &startMu_, "weight mu of -mu log(1 - y^2), y = (x - centre) / half-width, in the first round");
    declare("decrease", &decrease_, "factor on mu after each round");
    declare("rounds", &rounds_, "outer solves, each from the last one's iterate (1: mu fixed)");
    declare("boundary_fraction", &boundaryFraction_,
            "the fraction of its distance to a bound a step may take a parameter, in (0, 1]; "
            "1: steps tried whole, one reaching the bound rejected");
  }

  bool adjustStep(const BlockSystem& system, Eigen::VectorXd& dx) override {
    if (boundaryFraction_ == 1.0) return false;
    return limitBoundedSteps(system, dx, [this](const Bounds::Bound& bound, double x, double step) {
      const double room = boundaryFraction_ * (step > 0.0 ? bound.upper - x : x - bound.lower);
      return std::abs(step) > room ? std::copysign(room, step) : step;
    });
  }

  // The rounds share one optimizer and one set of barrier edges (only mu
  // changes), so every round after the first solves the structure the first
  // one set up.
  SolverSummary solve(Graph& graph, const SolverOptions& options) override {
    const double initialCost = graph.cost(options.threads);
    SolverSummary total;
    {
      Optimizer optimizer(options);
      mu_ = startMu_;
      keepEdges_ = true;
      const EdgeRemoval removal{*this, graph};
      for (round_ = 0; round_ < std::max(1, rounds_); ++round_, mu_ *= decrease_) {
        // A round's costs count the barrier; the total's are the graph's own, set below.
        const SolverSummary part = optimizer.optimize(graph, *this);
        if (round_ == 0)
          total = part;
        else
          appendSummary(total, part);
      }
    }
    // The graph's own costs, the barrier edges taken out.
    total.initialCost = initialCost;
    total.finalCost = graph.cost(options.threads);
    return total;
  }

  void begin(Graph& graph) override {
    if (!(boundaryFraction_ > 0.0 && boundaryFraction_ <= 1.0))
      throw Error("log_barrier: boundary_fraction must lie in (0, 1], got " + std::to_string(boundaryFraction_));
    // Later rounds start from the previous round's iterate, strictly inside
    // because its barrier cost was finite, however close to a bound.
    if (round_ == 0) enforceStart(true);
    if (!edges_.empty()) {
      for (BarrierEdge* edge : edges_) edge->setMu(mu_);
      return;
    }
    for (const Bounds::Bound& bound : bounds_.all()) {
      if (bound.vertex->fixed()) continue;
      edges_.push_back(
          graph.addEdge(std::make_unique<BarrierEdge>(bound.vertex, bound.index, bound.lower, bound.upper, mu_)));
    }
  }

  // A solve outside solve()'s rounds (an Optimizer given this method directly)
  // takes its edges out again at once.
  void end(Graph& graph) override {
    if (!keepEdges_) removeEdges(graph);
  }

 private:
  // Takes the barrier edges out of the graph when solve() leaves, however it leaves.
  struct EdgeRemoval {
    LogBarrier& method;
    Graph& graph;
    ~EdgeRemoval() {
      method.keepEdges_ = false;
      method.removeEdges(graph);
    }
  };

  void removeEdges(Graph& graph) {
    for (const Edge* edge : edges_) graph.removeEdge(edge);
    edges_.clear();
  }

  double startMu_ = 1e-2;
  double boundaryFraction_ = 0.995;
  double decrease_ = 0.1;
  int rounds_ = 3;
  double mu_ = 0.0;
  int round_ = 0;
  bool keepEdges_ = false;  // within solve(): the edges stay from round to round
  std::vector<BarrierEdge*> edges_;
};

}  // namespace

void addLogBarrier(Registry<ConstraintMethod>& registry) {
  registry.addType<LogBarrier>(
      "log_barrier",
      "the paper's log barrier: unary barrier edges with exact gradient and Hessian, mu decreased per round");
}
}  // namespace lrsvo
