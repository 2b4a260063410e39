#pragma once

#include "lrsvo/graph/symmetric_backend.h"

namespace lrsvo {

// The matrix held dense and factorised by Eigen's LLT (for systems of up to a
// few thousand unknowns: sliding windows, reduced camera systems).
class DenseBackend : public SymmetricBackend {
 public:
  void analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) override;
  BlockRef block(int k) override;
  void setZero() override { matrix_.setZero(); }
  bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) override;
  // No ordering; n^3 / 3 flops for n unknowns.
  FactorizationInfo factorization() const override;

 private:
  Eigen::MatrixXd matrix_;
  std::vector<int> offsets_;
  std::vector<std::pair<int, int>> pairs_;
};

}  // namespace lrsvo
