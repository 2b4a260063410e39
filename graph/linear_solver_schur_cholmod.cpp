#include "graph/cholmod_backend.h"
#include "graph/registry.h"
#include "graph/schur_solver.h"

namespace lrsvo {
namespace {
const Registrar<LinearSolver> kRegistrar(
    "schur_cholmod", [] { return std::make_unique<SchurSolver>(std::make_unique<CholmodBackend>()); },
    "Schur complement on marginalised vertices, CHOLMOD supernodal Cholesky of the reduced system");
}  // namespace
}  // namespace lrsvo
