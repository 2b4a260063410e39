#include "graph/dense_backend.h"
#include "graph/registry.h"
#include "graph/schur_solver.h"

namespace lrsvo {
namespace {
const Registrar<LinearSolver> kRegistrar(
    "schur_dense", [] { return std::make_unique<SchurSolver>(std::make_unique<DenseBackend>()); },
    "Schur complement on marginalised vertices, dense Cholesky of the reduced system");
}  // namespace
}  // namespace lrsvo
