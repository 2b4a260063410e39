#pragma once

#include <memory>

#include "lrsvo/graph/constraint_handler.h"
#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/solver_options.h"
#include "lrsvo/graph/solver_summary.h"

namespace lrsvo {

// Minimises a graph's cost with the algorithm and linear solver named in the
// options, under an optional constraint method.
//
// An optimizer keeps the block structure of its last solve and its linear
// solver's symbolic analysis: a later solve of a graph with the same structure
// (the same edges on the same vertices, each as fixed and marginalised as it
// was: BlockSystem::describes) starts from them and skips the set-up, as a
// sliding window's rounds or a user's repeated solves of one problem do.
// Anything else is set up afresh. What is kept is freed with the optimizer or
// by releaseStructure(). One optimizer serves one solve at a time.
class Optimizer {
 public:
  // Throws lrsvo::Error on invalid options (SolverOptions::validate).
  explicit Optimizer(SolverOptions options = {});
  ~Optimizer();
  // A copy takes the options; the kept structure stays with the original.
  Optimizer(const Optimizer& other);
  Optimizer& operator=(const Optimizer& other);
  Optimizer(Optimizer&&) noexcept;
  Optimizer& operator=(Optimizer&&) noexcept;

  const SolverOptions& options() const { return options_; }

  // Optimises the non-fixed vertices in place. Throws lrsvo::Error on bad
  // input: an empty graph, non-finite estimates or start cost (naming the
  // vertex or edge), unknown solver names.
  SolverSummary optimize(Graph& graph);
  // The same under a constraint method's hooks (see constraints/).
  SolverSummary optimize(Graph& graph, ConstraintHandler& constraints);

  // Frees the kept structure (the next solve sets up afresh).
  void releaseStructure();

 private:
  struct Prepared;

  SolverOptions options_;
  std::unique_ptr<Prepared> prepared_;
};

}  // namespace lrsvo
