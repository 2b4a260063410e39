#include "lrsvo/graph/dense_backend.h"

#include <Eigen/Cholesky>

#include "lrsvo/graph/openmp_thread_limit.h"

namespace lrsvo {

void DenseBackend::analyze(const std::vector<int>& blockDims, const std::vector<std::pair<int, int>>& blockPairs) {
  offsets_.assign(blockDims.size() + 1, 0);
  for (std::size_t i = 0; i < blockDims.size(); ++i) offsets_[i + 1] = offsets_[i] + blockDims[i];
  size_ = offsets_.back();
  values_.assign(static_cast<std::size_t>(size_ * size_), 0.0);
  pairs_ = blockPairs;
}

SymmetricBackend::BlockRef DenseBackend::block(int k) {
  const auto [row, col] = pairs_[k];
  return {values_.data() + offsets_[row] + static_cast<Eigen::Index>(offsets_[col]) * size_, static_cast<int>(size_)};
}

FactorizationInfo DenseBackend::factorization() const {
  const double n = static_cast<double>(size_);
  return {"dense", n * n * n / 3.0};
}

bool DenseBackend::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) {
  const OpenMpThreadLimit limit(threads);
  // In place: the matrix is filled again before every solve.
  Eigen::Map<Eigen::MatrixXd> m = matrix();
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Upper> llt(m);
  if (llt.info() != Eigen::Success) return false;
  x = llt.solve(rhs);
  return x.allFinite();
}

}  // namespace lrsvo
