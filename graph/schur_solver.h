#pragma once

#include <memory>
#include <vector>

#include "lrsvo/graph/linear_solver.h"
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

  // Number of blocks in the reduced system (for tests and diagnostics).
  int reducedBlockCount() const { return reducedBlockCount_; }

 private:
  using Kernel = void (*)(const double* y, const double* w, double* s, int ld, int di, int dl, int dj);
  struct Update {  // S[target] -= Y(i,l) W(j,l)^T
    int y;         // system block (i, l); Y is kept in the same slot
    int w;         // system block (j, l)
    int target;    // backend block (i, j)
    Kernel kernel;
  };
  struct Copy {  // S[target] += H[source] for free-free blocks
    int source;
    int target;
  };

  // V^-1 and Y = W V^-1 for marginalised vertex l; false if V is not positive definite.
  template <int DL>
  bool invertMarginal(const BlockSystem& system, int l);
  // Row i of S and of the reduced right-hand side.
  void reduceRow(const BlockSystem& system, const Eigen::VectorXd& rhs, int i, Eigen::VectorXd& reducedRhs);
  // x_l = V^-1 (r_l - sum_i W_il^T x_i).
  template <int DL>
  void backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs, const Eigen::VectorXd& xFree, int l,
                      Eigen::VectorXd& x) const;

  std::unique_ptr<SymmetricBackend> backend_;
  int reducedBlockCount_ = 0;
  std::vector<std::vector<Update>> rowUpdates_;
  std::vector<std::vector<Copy>> rowCopies_;
  std::vector<std::vector<int>> rowCouplings_;       // per free row i: system blocks (i, l)
  std::vector<std::vector<int>> marginalCouplings_;  // per marginalised l: system blocks (i, l)
  std::vector<double> rowWork_;                      // per free row i: its blocks' count, the cost of reduceRow
  std::vector<std::size_t> yOffsets_;                // per system block: offset of Y, if a coupling
  std::vector<double> yValues_;
  std::vector<std::size_t> vInverseOffsets_;  // per marginalised vertex
  std::vector<double> vInverseValues_;
};

}  // namespace lrsvo
