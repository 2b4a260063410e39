// `lrsvo solvers`: everything registered in the plugin registries, so a new
// plugin shows up here without editing this file.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/command.h"
#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/constraints/constraint_types.h"
#include "lrsvo/edges/edge_types.h"
#include "lrsvo/graph/edge.h"
#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/optimization_algorithm.h"
#include "lrsvo/graph/registry.h"
#include "lrsvo/graph/robust_kernel.h"
#include "lrsvo/graph/vertex.h"

namespace lrsvo::cli {
namespace {

template <typename Product>
std::size_t longestName() {
  std::size_t width = 0;
  for (const auto& [name, entry] : Registry<Product>::instance().entries()) width = std::max(width, name.size());
  return width;
}

template <typename Product>
void printRegistry(const char* title) {
  std::printf("%s\n", title);
  const int width = static_cast<int>(longestName<Product>());
  for (const auto& [name, entry] : Registry<Product>::instance().entries())
    std::printf("  %-*s  %s\n", width, name.c_str(), entry.description.c_str());
  std::printf("\n");
}

// Each method with its own settings and their defaults: a method is chosen as
// name[:setting=value,...].
void printConstraintMethods() {
  std::printf("Constraint methods (bounds on parameters; name[:setting=value,...]):\n");
  const int width = static_cast<int>(longestName<ConstraintMethod>());
  for (const auto& [name, entry] : Registry<ConstraintMethod>::instance().entries()) {
    std::printf("  %-*s  %s\n", width, name.c_str(), entry.description.c_str());
    const std::unique_ptr<ConstraintMethod> method = entry.factory();
    for (const MethodSetting& setting : method->ownSettings())
      std::printf("  %-*s    %s=%s  %s\n", width, "", setting.name.c_str(), setting.valueText().c_str(),
                  setting.description.c_str());
  }
  std::printf("\n");
}

void printSolverNames() {
  std::printf("Solver names (<algorithm>_<linear solver>, for --solver):\n");
  for (const auto& algorithm : Registry<OptimizationAlgorithm>::instance().entries()) {
    std::printf(" ");
    for (const auto& solver : Registry<LinearSolver>::instance().entries())
      std::printf(" %s_%s", algorithm.first.c_str(), solver.first.c_str());
    std::printf("\n");
  }
}

void listAll() {
  registerEdgeTypes();
  registerConstraintTypes();
  printRegistry<OptimizationAlgorithm>("Optimisation algorithms:");
  printRegistry<LinearSolver>("Linear solvers:");
  printSolverNames();
  std::printf("\n");
  printConstraintMethods();
  printRegistry<RobustKernel>("Robust kernels (--kernel):");
  printRegistry<Vertex>("Vertex types (graph file tags):");
  printRegistry<Edge>("Edge types (graph file tags):");
}

void addSolversCommand(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("solvers", "List the registered algorithms, linear solvers, kernels, vertex and edge types");
  command->footer("A solver is chosen by the name <algorithm>_<linear solver>, e.g. lm_schur_cholmod.");
  command->callback(listAll);
}

}  // namespace

LRSVO_REGISTER_COMMAND("solvers", addSolversCommand);

}  // namespace lrsvo::cli
