#include "lrsvo/graph/schur_solver.h"

#include <algorithm>
#include <cstddef>

#include "lrsvo/graph/balanced_ranges.h"
#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/graph/stopwatch.h"

namespace lrsvo {

namespace {

template <int DI, int DL, int DJ>
[[gnu::always_inline]] inline void subtractProduct(const double* y, const double* w, double* s, int ld, int di, int dl,
                                                   int dj) {
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

}  // namespace

template <int DL, int DF>
void SchurSolver::eliminatePoint(const BlockSystem& system, const Eigen::VectorXd& rhs, int l, int first, int last,
                                 Eigen::VectorXd& reducedRhs, double* y) const {
  // DF: the dimension of every free vertex when all are alike (cameras of 9,
  // poses of 6), so that the products below are of fixed size.
  using Coupling = Eigen::Matrix<double, DF, DL>;
  const auto& blocks = system.blocks();
  const std::span<const int> couplings = marginalCouplings(system, l);
  const auto rowBefore = [&](int coupling, int row) { return blocks[coupling].row < row; };
  const auto begin = std::lower_bound(couplings.begin(), couplings.end(), first, rowBefore);
  const auto end = std::lower_bound(begin, couplings.end(), last, rowBefore);
  if (begin == end) return;
  const int v = system.freeCount() + l, dl = system.dim(v);
  const Eigen::Map<const Eigen::Matrix<double, DL, DL>> vInverse(vInverses_.inverse(l), dl, dl);
  const Eigen::Matrix<double, DL, 1> rl = rhs.segment(system.offset(v), dl);
  for (auto a = begin; a != end; ++a) {
    const int i = blocks[*a].row, di = system.dim(i);
    Eigen::Map<Coupling> ym(y, di, dl);
    ym.noalias() = Eigen::Map<const Coupling>(system.values(blocks[*a]), di, dl) * vInverse;
    Eigen::Map<Eigen::Matrix<double, DF, 1>>(reducedRhs.data() + system.offset(i), di).noalias() -= ym * rl;
    // The rows j of the couplings from a on ascend, as do row i's columns of
    // S: each is found from the one before.
    auto column = columns_.begin() + static_cast<std::ptrdiff_t>(rowStart_[i]);
    const auto rowEnd = columns_.begin() + static_cast<std::ptrdiff_t>(rowStart_[i + 1]);
    for (auto b = a; b != couplings.end(); ++b) {
      const auto& w = blocks[*b];
      const int dj = system.dim(w.row);
      column = std::lower_bound(column, rowEnd, w.row);
      const SymmetricBackend::BlockRef target = targets_[column - columns_.begin()];
      if constexpr (DF != Eigen::Dynamic)
        subtractProduct<DF, DL, DF>(y, system.values(w), target.data, target.ld, di, dl, dj);
      else
        selectKernel<DL>(di, dj)(y, system.values(w), target.data, target.ld, di, dl, dj);
    }
  }
}

void SchurSolver::analyze(const BlockSystem& system) {
  vInverses_.analyze(system);
  const int freeCount = system.freeCount();
  const auto& blocks = system.blocks();

  // The pattern of S, row by row: the diagonal, H's free-free blocks of row i
  // (its blocks before the couplings, by column), and (i, j) for every pair of
  // rows i <= j coupled to one marginalised vertex.
  rowStart_.assign(1, 0);
  columns_.clear();
  rowCopies_.assign(freeCount, {});
  rowWork_.assign(freeCount, 0.0);
  std::vector<int> seenInRow(freeCount, -1);
  std::vector<int> row;
  for (int i = 0; i < freeCount; ++i) {
    row.clear();
    const auto add = [&](int j) {
      if (seenInRow[j] != i) {
        seenInRow[j] = i;
        row.push_back(j);
      }
    };
    for (int k : system.rowBlocks(i)) {
      rowWork_[i] += 1.0;
      if (blocks[k].col < freeCount) {
        add(blocks[k].col);
        continue;
      }
      const std::span<const int> couplings = marginalCouplings(system, blocks[k].col - freeCount);
      for (auto c = std::find(couplings.begin(), couplings.end(), k); c != couplings.end(); ++c) {
        add(blocks[*c].row);
        rowWork_[i] += 1.0;
      }
    }
    std::sort(row.begin(), row.end());
    columns_.insert(columns_.end(), row.begin(), row.end());
    rowStart_.push_back(columns_.size());
  }
  for (int i = 0; i < freeCount; ++i)
    for (int k : system.rowBlocks(i))
      if (blocks[k].col < freeCount) rowCopies_[i].push_back({k, reducedBlock(i, blocks[k].col)});

  freeDim_ = freeCount > 0 ? system.dim(0) : 0;
  for (int i = 0; i < freeCount; ++i)
    if (system.dim(i) != freeDim_) freeDim_ = 0;
  maxCouplingSize_ = 0;
  for (const auto& block : blocks)
    if (block.row < freeCount && block.col >= freeCount)
      maxCouplingSize_ =
          std::max(maxCouplingSize_, static_cast<std::size_t>(system.dim(block.row)) * system.dim(block.col));

  std::vector<int> dims(freeCount);
  for (int i = 0; i < freeCount; ++i) dims[i] = system.dim(i);
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(columns_.size());
  for (int i = 0; i < freeCount; ++i)
    for (std::size_t p = rowStart_[i]; p < rowStart_[i + 1]; ++p) pairs.emplace_back(i, columns_[p]);
  // With every active vertex marginalised there is no reduced system to factorise.
  targets_.clear();
  if (freeCount == 0) return;
  backend_->analyze(dims, pairs);
  for (int k = 0; k < reducedBlockCount(); ++k) targets_.push_back(backend_->block(k));
}

int SchurSolver::reducedBlock(int i, int j) const {
  const auto begin = columns_.begin() + static_cast<std::ptrdiff_t>(rowStart_[i]);
  const auto end = columns_.begin() + static_cast<std::ptrdiff_t>(rowStart_[i + 1]);
  return static_cast<int>(std::lower_bound(begin, end, j) - columns_.begin());
}

void SchurSolver::copyFreeBlocks(const BlockSystem& system, int i) {
  const auto& blocks = system.blocks();
  const int di = system.dim(i);
  for (const Copy& copy : rowCopies_[i]) {
    const auto target = targets_[copy.target];
    const auto& source = blocks[copy.source];
    const int dj = system.dim(source.col);
    Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>(target.data, di, dj, Eigen::OuterStride<>(target.ld)) +=
        Eigen::Map<const Eigen::MatrixXd>(system.values(source), di, dj);
  }
}

void SchurSolver::eliminate(const BlockSystem& system, const Eigen::VectorXd& rhs, int first, int last,
                            Eigen::VectorXd& reducedRhs) const {
  const int freeCount = system.freeCount();
  std::vector<double> y(maxCouplingSize_);
  constexpr int X = Eigen::Dynamic;
  for (int l = 0; l < system.blockCount() - freeCount; ++l) {
    if (system.dim(freeCount + l) != 3)
      eliminatePoint<X, X>(system, rhs, l, first, last, reducedRhs, y.data());
    else if (freeDim_ == 9)
      eliminatePoint<3, 9>(system, rhs, l, first, last, reducedRhs, y.data());
    else if (freeDim_ == 6)
      eliminatePoint<3, 6>(system, rhs, l, first, last, reducedRhs, y.data());
    else
      eliminatePoint<3, X>(system, rhs, l, first, last, reducedRhs, y.data());
  }
}

bool SchurSolver::solve(const BlockSystem& system, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, int threads) {
  Stopwatch phase;
  const int freeCount = system.freeCount();
  if (!vInverses_.compute(system, threads)) return false;

  // Reduced system, by rows of blocks. Row i holds the updates of every j >= i,
  // so the rows' costs fall along S: each task takes a contiguous range of
  // rows of about equal work (a few per thread, handed out as threads come
  // free; one range on one thread). Contiguous, so that two threads seldom
  // write neighbouring blocks of one column of S, which share cache lines.
  // Within a range the points are eliminated one by one.
  if (freeCount > 0) backend_->setZero();
  Eigen::VectorXd reducedRhs = rhs.head(system.freeScalarCount());
  const std::vector<int> ranges = balancedRanges(rowWork_, threads);
  parallelFor(0, static_cast<int>(ranges.size()) - 1, threads, 1, [&](int range) {
    for (int i = ranges[range]; i < ranges[range + 1]; ++i) copyFreeBlocks(system, i);
    eliminate(system, rhs, ranges[range], ranges[range + 1], reducedRhs);
  });
  const double reduceSeconds = phase.lap();

  Eigen::VectorXd xFree;
  const bool ok = freeCount == 0 || backend_->solve(reducedRhs, xFree, threads);
  const double solveSeconds = phase.lap();
  if (!ok) return false;

  const bool finite = vInverses_.backSubstitute(system, rhs, xFree, x, threads);
  times_.schurSeconds += reduceSeconds + phase.seconds();
  times_.factorizeSeconds += solveSeconds;
  return finite;
}

}  // namespace lrsvo
