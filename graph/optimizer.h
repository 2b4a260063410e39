#pragma once

#include "lrsvo/graph/constraint_handler.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/solver_options.h"
#include "lrsvo/graph/solver_summary.h"

namespace lrsvo {

// Minimises a graph's cost with the algorithm and linear solver named in the
// options, under an optional constraint method.
class Optimizer {
 public:
  // Throws lrsvo::Error on invalid options (SolverOptions::validate).
  explicit Optimizer(SolverOptions options = {});

  const SolverOptions& options() const { return options_; }

  // Optimises the non-fixed vertices in place. Throws lrsvo::Error on bad
  // input: an empty graph, non-finite estimates or start cost (naming the
  // vertex or edge), unknown solver names.
  SolverSummary optimize(Graph& graph) const;
  // The same under a constraint method's hooks (see constraints/).
  SolverSummary optimize(Graph& graph, ConstraintHandler& constraints) const;

 private:
  SolverOptions options_;
};

}  // namespace lrsvo
