#include "lrsvo/graph/full_solver.h"

#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

void FullSolver::analyze(const BlockSystem& system) {
  std::vector<int> dims(system.blockCount());
  for (int i = 0; i < system.blockCount(); ++i) dims[i] = system.dim(i);
  std::vector<std::pair<int, int>> pairs;
  for (const auto& block : system.blocks()) pairs.emplace_back(block.row, block.col);
  backend_->analyze(dims, pairs);
}

bool FullSolver::solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) {
  const Stopwatch start;
  backend_->setZero();
  const auto& blocks = system.blocks();
  parallelFor(0, static_cast<int>(blocks.size()), threads, [&](int k) {
    const SymmetricBackend::BlockRef target = backend_->block(k);
    const int rows = system.dim(blocks[k].row);
    const double* source = system.values(blocks[k]);
    for (int c = 0; c < system.dim(blocks[k].col); ++c)
      for (int r = 0; r < rows; ++r) target.data[c * target.ld + r] = source[c * rows + r];
  });
  const bool ok = backend_->solve(rhs, x, threads);
  times_.factorizeSeconds += start.seconds();
  return ok;
}

}  // namespace lrsvo
