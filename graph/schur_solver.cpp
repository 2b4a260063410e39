#include "lrsvo/graph/schur_solver.h"

#include <map>
#include <string>

#include <Eigen/Cholesky>

#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

namespace {

template <int DI, int DL, int DJ>
void subtractProduct(const double* y, const double* w, double* s, int ld, int di, int dl, int dj) {
  Eigen::Map<const Eigen::Matrix<double, DI, DL>> ym(y, di, dl);
  Eigen::Map<const Eigen::Matrix<double, DJ, DL>> wm(w, dj, dl);
  Eigen::Map<Eigen::Matrix<double, DI, DJ>, 0, Eigen::OuterStride<>> sm(s, di, dj, Eigen::OuterStride<>(ld));
  // lazyProduct: Eigen would send a 9-row product through its large-matrix GEMM.
  sm.noalias() -= ym.lazyProduct(wm.transpose());
}

// Fixed-size kernels for the shapes of bundle adjustment (poses of 6, BAL
// cameras of 9, points of 3); anything else takes the dynamic one.
template <int DL>
auto selectKernel(int di, int dj) {
  constexpr int X = Eigen::Dynamic;
  if (di == 6 && dj == 6) return &subtractProduct<6, DL, 6>;
  if (di == 9 && dj == 9) return &subtractProduct<9, DL, 9>;
  if (di == 6) return &subtractProduct<6, DL, X>;
  if (di == 9) return &subtractProduct<9, DL, X>;
  return &subtractProduct<X, DL, X>;
}

// Splits rows [0, work.size()) into at most `parts` contiguous ranges of about
// equal total work; returns the ranges' boundaries, first 0, last the row count.
std::vector<int> balancedRanges(const std::vector<double>& work, int parts) {
  double total = 0.0;
  for (double w : work) total += w;
  const int rows = static_cast<int>(work.size());
  std::vector<int> bounds{0};
  double done = 0.0;
  for (int i = 0; i + 1 < rows; ++i) {
    done += work[i];
    if (done >= total * static_cast<double>(bounds.size()) / parts) bounds.push_back(i + 1);
  }
  bounds.push_back(rows);
  return bounds;
}

}  // namespace

template <int DL>
bool SchurSolver::invertMarginal(const BlockSystem& system, int l) {
  using Square = Eigen::Matrix<double, DL, DL>;
  const int v = system.freeCount() + l, dl = system.dim(v);
  const auto& blocks = system.blocks();
  Eigen::LLT<Square> llt(Eigen::Map<const Square>(system.values(blocks[system.diagonalBlock(v)]), dl, dl));
  if (llt.info() != Eigen::Success) return false;
  Eigen::Map<Square> vInverse(vInverseValues_.data() + vInverseOffsets_[l], dl, dl);
  vInverse = llt.solve(Square::Identity(dl, dl));
  for (int k : marginalCouplings_[l]) {
    const int di = system.dim(blocks[k].row);
    using Coupling = Eigen::Matrix<double, Eigen::Dynamic, DL>;
    Eigen::Map<Coupling>(yValues_.data() + yOffsets_[k], di, dl).noalias() =
        Eigen::Map<const Coupling>(system.values(blocks[k]), di, dl) * vInverse;
  }
  return true;
}

template <int DL>
void SchurSolver::backSubstitute(const BlockSystem& system, const Eigen::VectorXd& rhs, const Eigen::VectorXd& xFree,
                                 int l, Eigen::VectorXd& x) const {
  using Vector = Eigen::Matrix<double, DL, 1>;
  using Coupling = Eigen::Matrix<double, Eigen::Dynamic, DL>;
  const int v = system.freeCount() + l, dl = system.dim(v);
  const auto& blocks = system.blocks();
  Vector r = rhs.segment(system.offset(v), dl);
  for (int k : marginalCouplings_[l]) {
    const int i = blocks[k].row, di = system.dim(i);
    r.noalias() -=
        Eigen::Map<const Coupling>(system.values(blocks[k]), di, dl).transpose() * xFree.segment(system.offset(i), di);
  }
  x.segment(system.offset(v), dl).noalias() =
      Eigen::Map<const Eigen::Matrix<double, DL, DL>>(vInverseValues_.data() + vInverseOffsets_[l], dl, dl) * r;
}

void SchurSolver::analyze(const BlockSystem& system) {
  const int freeCount = system.freeCount();
  const int marginalCount = system.blockCount() - freeCount;
  const auto& blocks = system.blocks();

  std::map<std::pair<int, int>, int> reduced;
  auto reducedBlock = [&](int i, int j) {
    return reduced.emplace(std::make_pair(i, j), static_cast<int>(reduced.size())).first->second;
  };
  for (int i = 0; i < freeCount; ++i) reducedBlock(i, i);

  rowCopies_.assign(freeCount, {});
  rowCouplings_.assign(freeCount, {});
  marginalCouplings_.assign(marginalCount, {});
  for (int k = 0; k < static_cast<int>(blocks.size()); ++k) {
    const auto& block = blocks[k];
    if (block.col < freeCount) {
      rowCopies_[block.row].push_back({k, reducedBlock(block.row, block.col)});
    } else if (block.row < freeCount) {
      rowCouplings_[block.row].push_back(k);
      marginalCouplings_[block.col - freeCount].push_back(k);
    } else if (block.row != block.col) {
      throw Error("Schur solver: an edge joins marginalised vertices " +
                  std::to_string(system.vertex(block.row)->id()) + " and " +
                  std::to_string(system.vertex(block.col)->id()) + "; use a full solver");
    }
  }

  rowUpdates_.assign(freeCount, {});
  for (int l = 0; l < marginalCount; ++l) {
    const int dl = system.dim(freeCount + l);
    for (int a : marginalCouplings_[l]) {
      for (int b : marginalCouplings_[l]) {
        const int i = blocks[a].row, j = blocks[b].row;
        if (i > j) continue;
        const Kernel kernel = dl == 3 ? selectKernel<3>(system.dim(i), system.dim(j))
                                      : selectKernel<Eigen::Dynamic>(system.dim(i), system.dim(j));
        rowUpdates_[i].push_back({a, b, reducedBlock(i, j), kernel});
      }
    }
  }
  rowWork_.assign(freeCount, 0.0);
  for (int i = 0; i < freeCount; ++i)
    rowWork_[i] = static_cast<double>(rowUpdates_[i].size() + rowCopies_[i].size() + rowCouplings_[i].size());

  yOffsets_.assign(blocks.size(), 0);
  std::size_t ySize = 0;
  for (const auto& couplings : marginalCouplings_)
    for (int k : couplings) {
      yOffsets_[k] = ySize;
      ySize += static_cast<std::size_t>(system.dim(blocks[k].row)) * system.dim(blocks[k].col);
    }
  yValues_.assign(ySize, 0.0);
  vInverseOffsets_.assign(marginalCount, 0);
  std::size_t vSize = 0;
  for (int l = 0; l < marginalCount; ++l) {
    vInverseOffsets_[l] = vSize;
    vSize += static_cast<std::size_t>(system.dim(freeCount + l)) * system.dim(freeCount + l);
  }
  vInverseValues_.assign(vSize, 0.0);

  std::vector<int> dims(freeCount);
  for (int i = 0; i < freeCount; ++i) dims[i] = system.dim(i);
  std::vector<std::pair<int, int>> pairs(reduced.size());
  for (const auto& [key, index] : reduced) pairs[index] = key;
  reducedBlockCount_ = static_cast<int>(pairs.size());
  // With every active vertex marginalised there is no reduced system to factorise.
  if (freeCount > 0) backend_->analyze(dims, pairs);
}

void SchurSolver::reduceRow(const BlockSystem& system, const Eigen::VectorXd& rhs, int i, Eigen::VectorXd& reducedRhs) {
  const auto& blocks = system.blocks();
  const int di = system.dim(i);
  for (const Copy& copy : rowCopies_[i]) {
    const auto target = backend_->block(copy.target);
    const auto& source = blocks[copy.source];
    const int dj = system.dim(source.col);
    Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>(target.data, di, dj, Eigen::OuterStride<>(target.ld)) +=
        Eigen::Map<const Eigen::MatrixXd>(system.values(source), di, dj);
  }
  for (const Update& update : rowUpdates_[i]) {
    const auto target = backend_->block(update.target);
    const auto& w = blocks[update.w];
    update.kernel(yValues_.data() + yOffsets_[update.y], system.values(w), target.data, target.ld, di,
                  system.dim(w.col), system.dim(w.row));
  }
  auto ri = reducedRhs.segment(system.offset(i), di);
  for (int k : rowCouplings_[i]) {
    const int l = blocks[k].col, dl = system.dim(l);
    ri.noalias() -=
        Eigen::Map<const Eigen::MatrixXd>(yValues_.data() + yOffsets_[k], di, dl) * rhs.segment(system.offset(l), dl);
  }
}

bool SchurSolver::solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) {
  Stopwatch phase;
  const int freeCount = system.freeCount();
  const int marginalCount = system.blockCount() - freeCount;

  // V^-1 per marginalised vertex and Y = W V^-1 per coupling.
  std::vector<char> positive(marginalCount, 1);
  parallelFor(0, marginalCount, threads, [&](int l) {
    positive[l] =
        system.dim(freeCount + l) == 3 ? invertMarginal<3>(system, l) : invertMarginal<Eigen::Dynamic>(system, l);
  });
  for (char p : positive)
    if (!p) return false;

  // Reduced system, by rows of blocks. Row i holds the updates of every j >= i,
  // so the rows' costs fall along S: each task takes a contiguous range of
  // rows of about equal work (a few per thread, handed out as threads come
  // free). Contiguous, so that two threads seldom write neighbouring blocks of
  // one column of S, which share cache lines.
  if (freeCount > 0) backend_->setZero();
  Eigen::VectorXd reducedRhs = rhs.head(system.freeScalarCount());
  const std::vector<int> ranges = balancedRanges(rowWork_, 4 * threads);
  parallelFor(0, static_cast<int>(ranges.size()) - 1, threads, 1, [&](int range) {
    for (int i = ranges[range]; i < ranges[range + 1]; ++i) reduceRow(system, rhs, i, reducedRhs);
  });
  const double reduceSeconds = phase.lap();

  Eigen::VectorXd xFree;
  const bool ok = freeCount == 0 || backend_->solve(reducedRhs, xFree);
  const double solveSeconds = phase.lap();
  if (!ok) return false;

  x.resize(system.scalarCount());
  x.head(xFree.size()) = xFree;
  parallelFor(0, marginalCount, threads, [&](int l) {
    if (system.dim(freeCount + l) == 3)
      backSubstitute<3>(system, rhs, xFree, l, x);
    else
      backSubstitute<Eigen::Dynamic>(system, rhs, xFree, l, x);
  });
  times_.schurSeconds += reduceSeconds + phase.seconds();
  times_.factorizeSeconds += solveSeconds;
  return x.allFinite();
}

}  // namespace lrsvo
