#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/cholmod_backend.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/schur_solver.h"

namespace lrsvo {
void addSchurCholmodSolver(Registry<LinearSolver>& registry) {
  registry.add(
      "schur_cholmod", [] { return std::make_unique<SchurSolver>(std::make_unique<CholmodBackend>()); },
      "Schur complement on marginalised vertices, CHOLMOD sparse Cholesky of the reduced system");
}
}  // namespace lrsvo
