#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/graph/linear_solver.h"

namespace lrsvo {

// Storage and factorisation of a symmetric positive definite matrix given as
// blocks (row <= col, every diagonal block present). Only the upper triangle
// is read; writers may fill diagonal blocks whole.
class SymmetricBackend {
 public:
  struct BlockRef {
    double* data;  // column-major
    int ld;        // leading dimension
  };

  virtual ~SymmetricBackend() = default;
  virtual void analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) = 0;
  // Block k of the pairs given to analyze().
  virtual BlockRef block(int k) = 0;
  virtual void setZero() = 0;
  // Factorises and solves on at most `threads` threads; false when the
  // matrix is not positive definite. The values may be overwritten by the
  // factor: fill them again before the next solve.
  virtual bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) = 0;
  // After analyze().
  virtual FactorizationInfo factorization() const = 0;
};

}  // namespace lrsvo
