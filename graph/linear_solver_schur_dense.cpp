#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/dense_backend.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/schur_solver.h"

namespace lrsvo {
void addSchurDenseSolver(Registry<LinearSolver>& registry) {
  registry.add(
      "schur_dense", [] { return std::make_unique<SchurSolver>(std::make_unique<DenseBackend>()); },
      "Schur complement on marginalised vertices, dense Cholesky of the reduced system");
}
}  // namespace lrsvo
