#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/dense_backend.h"
#include "lrsvo/graph/full_solver.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
void addDenseSolver(Registry<LinearSolver>& registry) {
  registry.add(
      "dense", [] { return std::make_unique<FullSolver>(std::make_unique<DenseBackend>()); },
      "dense Cholesky (Eigen LLT) of the whole system");
}
}  // namespace lrsvo
