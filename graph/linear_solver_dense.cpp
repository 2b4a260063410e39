#include "graph/dense_backend.h"
#include "graph/full_solver.h"
#include "graph/registry.h"

namespace lrsvo {
namespace {
const Registrar<LinearSolver> kRegistrar(
    "dense", [] { return std::make_unique<FullSolver>(std::make_unique<DenseBackend>()); },
    "dense Cholesky (Eigen LLT) of the whole system");
}  // namespace
}  // namespace lrsvo
