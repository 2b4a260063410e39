#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "lrsvo/graph/linear_solver.h"
#include "lrsvo/graph/marginal_block_inverses.h"
#include "lrsvo/graph/symmetric_backend.h"

namespace lrsvo {

// Eliminates marginalised vertices (points) block by block and solves the
// reduced system S = U - W V^-1 W^T of the free vertices with a backend:
//
//   [U   W] [xa]   [ra]      S xa = ra - W V^-1 rp
//   [W^T V] [xp] = [rp]      xp   = V^-1 (rp - W^T xa)
//
// S has a block (i, j) where H has one or where vertices i and j share a
// marginalised vertex, and no other: a vertex shared by every pose (the
// stereo extrinsic, kappa) is one dense block row and column, so S is an
// arrowhead over the pose blocks and stays sparse for the CHOLMOD backend.
// Work is split by contiguous ranges of rows of S, so that threads never
// write the same block.
class SchurSolver : public LinearSolver {
 public:
  explicit SchurSolver(std::unique_ptr<SymmetricBackend> backend) : backend_(std::move(backend)) {}
  bool usesSchurOrdering() const override { return true; }
  void analyze(const BlockSystem& system) override;
  bool solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;
  FactorizationInfo factorization() const override { return backend_->factorization(); }

  // Number of blocks in the reduced system (for tests and diagnostics).
  int reducedBlockCount() const { return static_cast<int>(columns_.size()); }

 private:
  struct Copy {  // S[target] += H[source] for free-free blocks
    int source;
    int target;
  };

  // Row i of S before the eliminations: its free-free blocks of H.
  void copyFreeBlocks(const BlockSystem& system, int i);
  // Eliminates every marginalised vertex from the rows [first, last) of S and
  // of the reduced right-hand side, point by point: S(i, j) -= Y_il W_jl^T
  // and r_i -= Y_il r_l with Y_il = W_il V_l^-1, formed when needed. A point's
  // blocks stay in cache for all its pairs, and each block of S takes its
  // updates in the order of l, whatever the split into rows (so the result
  // does not depend on the thread count).
  void eliminate(const BlockSystem& system, const Eigen::VectorXd& rhs, int first, int last,
                 Eigen::VectorXd& reducedRhs) const;
  template <int DL, int DF>
  void eliminatePoint(const BlockSystem& system, const Eigen::VectorXd& rhs, int l, int first, int last,
                      Eigen::VectorXd& reducedRhs, double* y) const;
  // Backend block index of S(i, j), a block of the pattern.
  int reducedBlock(int i, int j) const;

  std::unique_ptr<SymmetricBackend> backend_;
  // The pattern of S by rows: row i's block columns (ascending) are
  // columns_[rowStart_[i], rowStart_[i + 1]), and the position there is the
  // backend's block index.
  std::vector<std::size_t> rowStart_;
  std::vector<int> columns_;
  std::vector<SymmetricBackend::BlockRef> targets_;  // per backend block, fixed by its analyze()
  std::vector<std::vector<Copy>> rowCopies_;
  std::vector<double> rowWork_;      // per free row i: its updates and blocks, its share of the work
  std::size_t maxCouplingSize_ = 0;  // the largest W_il's entry count
  int freeDim_ = 0;                  // every free vertex's dimension when they agree, else 0
  MarginalBlockInverses vInverses_;
};

}  // namespace lrsvo
