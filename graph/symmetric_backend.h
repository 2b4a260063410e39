#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

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
  // Factorises and solves; false when the matrix is not positive definite.
  virtual bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) = 0;
};

}  // namespace lrsvo
