#pragma once

#include <cholmod.h>

#include "lrsvo/graph/symmetric_backend.h"

namespace lrsvo {

// The matrix held as CHOLMOD's compressed-column upper triangle and factorised
// by its supernodal Cholesky. Blocks are written straight into the column
// storage: each block column has the same row pattern in all of its columns,
// so a block is a column-major array whose leading dimension is that
// column's length. Diagonal blocks are stored whole; CHOLMOD reads only
// their upper part (stype > 0). Symbolic analysis (AMD ordering) runs once.
class CholmodBackend : public SymmetricBackend {
 public:
  CholmodBackend();
  ~CholmodBackend() override;
  CholmodBackend(const CholmodBackend&) = delete;
  CholmodBackend& operator=(const CholmodBackend&) = delete;

  void analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) override;
  BlockRef block(int k) override { return blocks_[k]; }
  void setZero() override;
  bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override;

 private:
  void release();

  cholmod_common common_;
  cholmod_sparse* matrix_ = nullptr;
  cholmod_factor* factor_ = nullptr;
  std::vector<BlockRef> blocks_;
};

}  // namespace lrsvo
