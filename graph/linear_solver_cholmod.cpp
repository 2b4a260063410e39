#include "graph/cholmod_backend.h"
#include "graph/full_solver.h"
#include "graph/registry.h"

namespace lrsvo {
namespace {
const Registrar<LinearSolver> kRegistrar(
    "cholmod", [] { return std::make_unique<FullSolver>(std::make_unique<CholmodBackend>()); },
    "sparse supernodal Cholesky (CHOLMOD) of the whole system");
}  // namespace
}  // namespace lrsvo
