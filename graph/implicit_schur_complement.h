#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/marginal_block_inverses.h"

namespace lrsvo {

// The reduced system S xa = b of the Schur solvers (see schur_solver.h),
// applied to vectors without ever being formed:
//
//   S x = U x - sum_l W_l z_l,  z_l = V_l^-1 sum_i W_il^T x_i,
//   b   = r_a - sum_l W_l u_l,  u_l = V_l^-1 r_l,
//
// read from the blocks of H in one pass over the marginalised vertices, each
// vertex's couplings read twice while they are in cache. The vertices are cut
// into a fixed number of chunks, each summing into a vector of its own, and the
// chunks are added in order: a product does not depend on the thread count.
// Storing nothing of S, it suits systems whose S would be too large to
// factorise; its diagonal blocks (for preconditioners) are formed.
class ImplicitSchurComplement {
 public:
  // Sizes the work space; throws lrsvo::Error when an edge joins two
  // marginalised vertices.
  void analyze(const BlockSystem& system);
  // Inverts every V_l of the current blocks and forms b from rhs; false when
  // a V_l is not positive definite.
  bool prepare(const BlockSystem& system, const Eigen::VectorXd& rhs, int threads);
  const Eigen::VectorXd& reducedRhs() const { return reducedRhs_; }
  // y = S x (x and y of the free vertices' size).
  void multiply(const BlockSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& y, int threads);
  // Inverts the diagonal blocks of S (U_ii - sum_l W_il V_l^-1 W_il^T, the
  // Schur-Jacobi blocks) or, without couplings, those of U; false when one is
  // not positive definite.
  bool invertDiagonalBlocks(const BlockSystem& system, bool withCouplings, int threads);
  // y = D^-1 x with the blocks of the last invertDiagonalBlocks().
  void applyDiagonalInverse(const BlockSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // The whole step from its free part (MarginalBlockInverses::backSubstitute).
  bool backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs, const Eigen::VectorXd& xFree,
                      Eigen::VectorXd& x, int threads) const {
    return vInverses_.backSubstitute(system, rhs, xFree, x, threads);
  }

 private:
  // y -= sum_l W_l V_l^-1 t_l with t_l = sum_i W_il^T x_i, or t_l = r_l when
  // x is null.
  void subtractEliminated(const BlockSystem& system, const Eigen::VectorXd* x, const Eigen::VectorXd& rhs,
                          Eigen::VectorXd& y, int threads);
  template <int DL>
  void subtractEliminated(const BlockSystem& system, const Eigen::VectorXd* x, const Eigen::VectorXd& rhs, int l,
                          double* partial) const;
  // Runs start(c) then body(c, l) for every marginalised vertex l of chunk c,
  // the chunks on up to `threads` threads.
  template <typename Body, typename Start>
  void forEachChunk(const BlockSystem& system, int threads, const Body& body, const Start& start) const;
  // y = U x.
  void multiplyFree(const BlockSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& y, int threads) const;
  template <int DI>
  bool invertDiagonalBlock(const BlockSystem& system, bool withCouplings, int i);

  // Where each coupling W_il's row sits in x, in the order of l then i: the
  // passes over the points read these and the couplings' values in a stream.
  struct CouplingRow {
    int offset;
    int dim;
  };

  MarginalBlockInverses vInverses_;
  std::vector<std::size_t> couplingStart_;  // per marginalised vertex, into couplingRows_
  std::vector<std::size_t> columnOffsets_;  // per marginalised vertex, where its column's values start
  std::vector<CouplingRow> couplingRows_;
  Eigen::MatrixXd partials_;          // a column per chunk of marginalised vertices
  Eigen::MatrixXd diagonalPartials_;  // the same for S's diagonal blocks, when formed
  Eigen::VectorXd reducedRhs_;
  std::vector<std::size_t> diagonalOffsets_;  // per free vertex
  std::vector<double> diagonalInverses_;
};

}  // namespace lrsvo
