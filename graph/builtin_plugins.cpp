#include "lrsvo/graph/builtin_plugins.h"

namespace lrsvo {

void LinearSolver::addBuiltins(Registry<LinearSolver>& registry) {
  addDenseSolver(registry);
  addCholmodSolver(registry);
  addSchurDenseSolver(registry);
  addSchurCholmodSolver(registry);
  addSchurPcgSolver(registry);
  addSchurPowerSeriesSolver(registry);
}

void OptimizationAlgorithm::addBuiltins(Registry<OptimizationAlgorithm>& registry) {
  addGaussNewton(registry);
  addLevenbergMarquardt(registry);
}

}  // namespace lrsvo
