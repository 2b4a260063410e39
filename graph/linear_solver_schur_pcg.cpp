#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/schur_pcg_solver.h"

namespace lrsvo {
void addSchurPcgSolver(Registry<LinearSolver>& registry) {
  registry.add(
      "schur_pcg", [] { return std::make_unique<SchurPcgSolver>(); },
      "Schur complement on marginalised vertices, never formed: conjugate gradients preconditioned by its diagonal "
      "blocks (inexact steps, Nash-Sofer eta 0.1)");
}
}  // namespace lrsvo
