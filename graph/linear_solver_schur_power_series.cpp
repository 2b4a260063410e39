#include "lrsvo/graph/builtin_plugins.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/schur_power_series_solver.h"

namespace lrsvo {
void addSchurPowerSeriesSolver(Registry<LinearSolver>& registry) {
  registry.add(
      "schur_power_series", [] { return std::make_unique<SchurPowerSeriesSolver>(); },
      "Schur complement on marginalised vertices, never formed: power series of its inverse (bundle adjustment "
      "structure only; inexact steps, summed until the estimated rest is 1 % of the sum)");
}
}  // namespace lrsvo
