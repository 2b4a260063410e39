#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/cholmod_backend.h"
#include "lrsvo/graph/full_solver.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
void addCholmodSolver(Registry<LinearSolver>& registry) {
  registry.add(
      "cholmod", [] { return std::make_unique<FullSolver>(std::make_unique<CholmodBackend>()); },
      "sparse Cholesky (CHOLMOD, supernodal or simplicial) of the whole system");
}
}  // namespace lrsvo
