#pragma once

#include <algorithm>

#include <Eigen/Core>

#include "lrsvo/graph/large_array.h"
#include "lrsvo/graph/symmetric_backend.h"

namespace lrsvo {

// The matrix held dense and factorised by Eigen's LLT (for systems of up to a
// few thousand unknowns: sliding windows, reduced camera systems). Its values
// are a LargeArray: a reduced camera system of 1 350 unknowns is 14.6 MB, and
// the Schur elimination's block updates stride across its columns, so on
// small pages nearly every column of a block costs a TLB miss.
class DenseBackend : public SymmetricBackend {
 public:
  void analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) override;
  BlockRef block(int k) override;
  void setZero() override { std::fill(values_.begin(), values_.end(), 0.0); }
  bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;
  // No ordering; n^3 / 3 flops for n unknowns.
  FactorizationInfo factorization() const override;

 private:
  Eigen::Map<Eigen::MatrixXd> matrix() { return {values_.data(), size_, size_}; }

  Eigen::Index size_ = 0;
  LargeArray<double> values_;  // column-major, size_ x size_
  std::vector<int> offsets_;
  std::vector<std::pair<int, int>> pairs_;
};

}  // namespace lrsvo
