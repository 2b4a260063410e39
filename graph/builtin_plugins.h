#pragma once

#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {

// Each of the graph library's plugins adds itself to its registry from its own
// source file; builtin_plugins.cpp calls them all (Product::addBuiltins).
void addDenseSolver(Registry<LinearSolver>& registry);
void addCholmodSolver(Registry<LinearSolver>& registry);
void addSchurDenseSolver(Registry<LinearSolver>& registry);
void addSchurCholmodSolver(Registry<LinearSolver>& registry);
void addSchurPcgSolver(Registry<LinearSolver>& registry);
void addSchurPowerSeriesSolver(Registry<LinearSolver>& registry);
void addGaussNewton(Registry<OptimizationAlgorithm>& registry);
void addLevenbergMarquardt(Registry<OptimizationAlgorithm>& registry);

}  // namespace lrsvo
