#include "lrsvo/graph/marginal_block_inverses.h"

#include <string>

#include <Eigen/Cholesky>

#include "lrsvo/graph/block_kernels.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"

namespace lrsvo {

void MarginalBlockInverses::analyze(const BlockSystem& system) {
  const int freeCount = system.freeCount(), marginalCount = system.blockCount() - freeCount;
  for (const auto& block : system.blocks())
    if (block.row >= freeCount && block.row != block.col)
      throw Error("Schur solver: an edge joins marginalised vertices " +
                  std::to_string(system.vertex(block.row)->id()) + " and " +
                  std::to_string(system.vertex(block.col)->id()) + "; use a full solver");
  offsets_.assign(marginalCount, 0);
  std::size_t size = 0;
  for (int l = 0; l < marginalCount; ++l) {
    offsets_[l] = size;
    size += static_cast<std::size_t>(system.dim(freeCount + l)) * system.dim(freeCount + l);
  }
  values_.assign(size, 0.0);
}

template <int DL>
bool MarginalBlockInverses::invert(const BlockSystem& system, int l) {
  using Square = Eigen::Matrix<double, DL, DL>;
  const int v = system.freeCount() + l, dl = system.dim(v);
  Eigen::LLT<Square> llt(Eigen::Map<const Square>(system.values(system.blocks()[system.diagonalBlock(v)]), dl, dl));
  if (llt.info() != Eigen::Success) return false;
  Eigen::Map<Square>(values_.data() + offsets_[l], dl, dl) = llt.solve(Square::Identity(dl, dl));
  return true;
}

bool MarginalBlockInverses::compute(const BlockSystem& system, int threads) {
  const int freeCount = system.freeCount(), marginalCount = system.blockCount() - freeCount;
  std::vector<char> positive(marginalCount, 1);
  parallelFor(0, marginalCount, threads, [&](int l) {
    positive[l] = system.dim(freeCount + l) == 3 ? invert<3>(system, l) : invert<Eigen::Dynamic>(system, l);
  });
  for (char p : positive)
    if (!p) return false;
  return true;
}

template <int DL>
void MarginalBlockInverses::backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs, int l,
                                           Eigen::VectorXd& x) const {
  using Vector = Eigen::Matrix<double, DL, 1>;
  const int v = system.freeCount() + l, dl = system.dim(v);
  const auto& blocks = system.blocks();
  Vector r = rhs.segment(system.offset(v), dl);
  for (int k : marginalCouplings(system, l)) {
    const int i = blocks[k].row;
    kernels::accumulateBlock<true>(system.values(blocks[k]), x.data() + system.offset(i), r.data(), system.dim(i), dl,
                                   -1.0);
  }
  x.segment(system.offset(v), dl).noalias() =
      Eigen::Map<const Eigen::Matrix<double, DL, DL>>(values_.data() + offsets_[l], dl, dl) * r;
}

bool MarginalBlockInverses::backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs,
                                           const Eigen::VectorXd& xFree, Eigen::VectorXd& x, int threads) const {
  x.resize(system.scalarCount());
  x.head(xFree.size()) = xFree;
  const int freeCount = system.freeCount();
  parallelFor(0, system.blockCount() - freeCount, threads, [&](int l) {
    if (system.dim(freeCount + l) == 3)
      backSubstitute<3>(system, rhs, l, x);
    else
      backSubstitute<Eigen::Dynamic>(system, rhs, l, x);
  });
  return x.allFinite();
}

}  // namespace lrsvo
