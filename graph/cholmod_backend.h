#pragma once

#include <cholmod.h>

#include "lrsvo/graph/symmetric_backend.h"

namespace lrsvo {

// The matrix held as CHOLMOD's compressed-column upper triangle and factorised
// by its Cholesky LL': supernodal, or simplicial where the supernodes are too
// small to pay for their dense kernels. Blocks are written straight into the column
// storage: each block column has the same row pattern in all of its columns,
// so a block is a column-major array whose leading dimension is that
// column's length. Diagonal blocks are stored whole; CHOLMOD reads only
// their upper part (stype > 0). Symbolic analysis runs once per structure.
//
// The fill-reducing ordering: CHOLMOD's own choice is AMD, with METIS tried
// beside it only when AMD's factor is both much fuller than the matrix and
// dense in flops per entry. Lattices such as pose graphs fill in heavily at
// fewer flops per entry, where nested dissection still cuts the work
// (unit_tests/graph/test_cholmod_ordering.cpp). So kLeastWork, wherever the
// factor is at least five times as full as the matrix, also dissects the graph
// of blocks (one node per vertex) with METIS and with CHOLMOD's NESDIS, and
// keeps the ordering whose factorisation takes the fewest flops. The block
// graph is a sixth of a pose graph's scalar one per side, so it is dissected
// faster, and a vertex's unknowns stay together in the order. Systems without
// such fill (the window's, BAL's reduced camera systems) never pay for it.
enum class CholmodOrdering { kLeastWork, kAmd };

class CholmodBackend : public SymmetricBackend {
 public:
  explicit CholmodBackend(CholmodOrdering ordering = CholmodOrdering::kLeastWork);
  ~CholmodBackend() override;
  CholmodBackend(const CholmodBackend&) = delete;
  CholmodBackend& operator=(const CholmodBackend&) = delete;

  void analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) override;
  BlockRef block(int k) override { return blocks_[k]; }
  void setZero() override;
  bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;

  // After analyze(): the ordering chosen ("amd", "metis", "nesdis", ...) and
  // the flops of one factorisation with it, as CHOLMOD counts them.
  const char* orderingName() const { return orderingName_; }
  double factorizationFlops() const { return factorizationFlops_; }
  FactorizationInfo factorization() const override { return {orderingName_, factorizationFlops_}; }
  // After analyze(): whether the factorisation is supernodal (else simplicial).
  bool supernodal() const { return factor_ && factor_->is_super; }

 private:
  void release();
  // Keeps the nested dissection of the block graph with fewer flops than the
  // current factor, if any. offsets: each block's first scalar and the total;
  // columnPairs: each block column's pairs (indices into blockPairs) in row order.
  void tryNestedDissection(const std::vector<int>& offsets, const std::vector<std::vector<int>>& columnPairs,
                           const std::vector<std::pair<int, int>>& blockPairs);
  // The matrix analysed with this scalar permutation (postordered by CHOLMOD)
  // for one factorisation kind (CHOLMOD_SIMPLICIAL or CHOLMOD_SUPERNODAL), the
  // default settings kept; null when CHOLMOD fails. Common's flop and fill
  // counts are then this analysis'.
  cholmod_factor* analyzeWith(const int* permutation, int kind);
  // Re-analyses for the simplicial factorisation when the supernodes average
  // fewer than kMinFlopsPerSupernode flops.
  void chooseFactorizationKind();

  CholmodOrdering ordering_;
  const char* orderingName_ = "none";
  double factorizationFlops_ = 0.0;
  cholmod_common common_;
  cholmod_sparse* matrix_ = nullptr;
  cholmod_factor* factor_ = nullptr;
  std::vector<BlockRef> blocks_;
};

}  // namespace lrsvo
