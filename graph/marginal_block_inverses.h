#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/graph/block_system.h"

namespace lrsvo {

// The couplings (i, l) of marginalised vertex l (block freeCount + l), by row:
// its column of H without the diagonal block, which comes last.
inline std::span<const int> marginalCouplings(const BlockSystem& system, int l) {
  const std::span<const int> column = system.colBlocks(system.freeCount() + l);
  return column.first(column.size() - 1);
}

// The inverses V_l^-1 of the marginalised vertices' diagonal blocks, which
// every Schur solver needs, and the back-substitution that recovers their
// steps once the free vertices' are known:
//
//   x_l = V_l^-1 (r_l - sum_i W_il^T x_i).
class MarginalBlockInverses {
 public:
  // Sizes the storage for the system's structure; throws lrsvo::Error when an
  // edge joins two marginalised vertices (they cannot be eliminated one by one).
  void analyze(const BlockSystem& system);
  // Inverts every V_l of the current (shifted) blocks; false when one is not
  // positive definite.
  bool compute(const BlockSystem& system, int threads);
  // V_l^-1, column-major, dim x dim.
  const double* inverse(int l) const { return values_.data() + offsets_[l]; }
  // The whole step x from its free part xFree: x's marginalised entries by
  // back-substitution. False when x is not finite.
  bool backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs, const Eigen::VectorXd& xFree,
                      Eigen::VectorXd& x, int threads) const;

 private:
  template <int DL>
  bool invert(const BlockSystem& system, int l);
  template <int DL>
  void backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs, int l, Eigen::VectorXd& x) const;

  std::vector<std::size_t> offsets_;  // per marginalised vertex
  std::vector<double> values_;
};

}  // namespace lrsvo
