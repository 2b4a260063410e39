#include "lrsvo/graph/implicit_schur_complement.h"

#include <algorithm>

#include <Eigen/Cholesky>

#include "lrsvo/graph/block_kernels.h"
#include "lrsvo/graph/parallel_for.h"

namespace lrsvo {

namespace {

using kernels::accumulateBlock;
using kernels::BlockMap;
using kernels::subtractCongruence;

// Chunks of marginalised vertices that sum into vectors of their own: enough
// for threads to share the work evenly, few enough that adding them is cheap,
// and no more than their sums' storage (kPartialEntries doubles, 64 MB) allows.
// The count depends on the structure only, never on the thread count.
constexpr std::size_t kChunks = 32;
constexpr std::size_t kPartialEntries = std::size_t{8} << 20;

}  // namespace

void ImplicitSchurComplement::analyze(const BlockSystem& system) {
  vInverses_.analyze(system);
  const int marginalCount = system.blockCount() - system.freeCount();
  couplingStart_.assign(1, 0);
  couplingRows_.clear();
  columnOffsets_.resize(marginalCount);
  for (int l = 0; l < marginalCount; ++l) {
    columnOffsets_[l] = system.blocks()[system.colBlocks(system.freeCount() + l).front()].offset;
    for (int k : marginalCouplings(system, l)) {
      const int i = system.blocks()[k].row;
      couplingRows_.push_back({system.offset(i), system.dim(i)});
    }
    couplingStart_.push_back(couplingRows_.size());
  }
  diagonalOffsets_.assign(system.freeCount(), 0);
  std::size_t size = 0;
  for (int i = 0; i < system.freeCount(); ++i) {
    diagonalOffsets_[i] = size;
    size += static_cast<std::size_t>(system.dim(i)) * system.dim(i);
  }
  diagonalInverses_.assign(size, 0.0);
  diagonalPartials_.resize(0, 0);
  const std::size_t chunkSize = std::max<std::size_t>({1, size, static_cast<std::size_t>(system.freeScalarCount())});
  const std::size_t chunks =
      std::min<std::size_t>({kChunks, static_cast<std::size_t>(system.blockCount() - system.freeCount()),
                             std::max<std::size_t>(1, kPartialEntries / chunkSize)});
  partials_.setZero(system.freeScalarCount(), static_cast<Eigen::Index>(chunks));
}

template <typename Body, typename Start>
void ImplicitSchurComplement::forEachChunk(const BlockSystem& system, int threads, const Body& body,
                                           const Start& start) const {
  const int marginalCount = system.blockCount() - system.freeCount();
  const int chunks = static_cast<int>(partials_.cols());
  parallelFor(0, chunks, threads, 1, [&](int c) {
    start(c);
    const int first = static_cast<int>(static_cast<long long>(marginalCount) * c / chunks);
    const int last = static_cast<int>(static_cast<long long>(marginalCount) * (c + 1) / chunks);
    for (int l = first; l < last; ++l) body(c, l);
  });
}

template <int DL>
void ImplicitSchurComplement::subtractEliminated(const BlockSystem& system, const Eigen::VectorXd* x,
                                                 const Eigen::VectorXd& rhs, int l, double* partial) const {
  using Vector = Eigen::Matrix<double, DL, 1>;
  const int v = system.freeCount() + l, dl = system.dim(v);
  const CouplingRow* first = couplingRows_.data() + couplingStart_[l];
  const CouplingRow* last = couplingRows_.data() + couplingStart_[l + 1];
  // The couplings' values, one block after another (BlockSystem::colBlocks).
  const double* columnValues = system.valueData() + columnOffsets_[l];
  Vector t(dl);
  if (x) {
    t.setZero();
    const double* w = columnValues;
    for (const CouplingRow* row = first; row != last; w += row->dim * dl, ++row)
      accumulateBlock<true>(w, x->data() + row->offset, t.data(), row->dim, dl, 1.0);
  } else {
    t = rhs.segment(system.offset(v), dl);
  }
  const Vector z = BlockMap<DL, DL>(vInverses_.inverse(l), dl, dl) * t;
  const double* w = columnValues;
  for (const CouplingRow* row = first; row != last; w += row->dim * dl, ++row)
    accumulateBlock<false>(w, z.data(), partial + row->offset, row->dim, dl, -1.0);
}

void ImplicitSchurComplement::subtractEliminated(const BlockSystem& system, const Eigen::VectorXd* x,
                                                 const Eigen::VectorXd& rhs, Eigen::VectorXd& y, int threads) {
  const int freeCount = system.freeCount();
  forEachChunk(
      system, threads,
      [&](int c, int l) {
        double* partial = partials_.col(c).data();
        if (system.dim(freeCount + l) == 3)
          subtractEliminated<3>(system, x, rhs, l, partial);
        else
          subtractEliminated<Eigen::Dynamic>(system, x, rhs, l, partial);
      },
      [&](int c) { partials_.col(c).setZero(); });
  // The chunks' sums, in chunk order, by stretches of y.
  const int chunks = static_cast<int>(partials_.cols());
  constexpr int kStretch = 1024;
  const int size = static_cast<int>(y.size());
  parallelFor(0, (size + kStretch - 1) / kStretch, threads, 1, [&](int s) {
    const int first = s * kStretch, length = std::min(kStretch, size - first);
    for (int c = 0; c < chunks; ++c) y.segment(first, length) += partials_.col(c).segment(first, length);
  });
}

void ImplicitSchurComplement::multiplyFree(const BlockSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& y,
                                           int threads) const {
  const int freeCount = system.freeCount();
  const auto& blocks = system.blocks();
  y.resize(system.freeScalarCount());
  parallelFor(0, freeCount, threads, [&](int i) {
    const int di = system.dim(i);
    double* yi = y.data() + system.offset(i);
    Eigen::Map<Eigen::VectorXd>(yi, di).setZero();
    for (int k : system.rowBlocks(i)) {
      const int j = blocks[k].col;
      if (j >= freeCount) break;  // the couplings come after the free columns
      accumulateBlock<false>(system.values(blocks[k]), x.data() + system.offset(j), yi, di, system.dim(j), 1.0);
    }
    const std::span<const int> above = system.colBlocks(i);  // U_ji for j < i, then the diagonal
    for (int k : above.first(above.size() - 1)) {
      const int j = blocks[k].row;
      accumulateBlock<true>(system.values(blocks[k]), x.data() + system.offset(j), yi, system.dim(j), di, 1.0);
    }
  });
}

bool ImplicitSchurComplement::prepare(const BlockSystem& system, const Eigen::VectorXd& rhs, int threads) {
  if (!vInverses_.compute(system, threads)) return false;
  reducedRhs_ = rhs.head(system.freeScalarCount());
  subtractEliminated(system, nullptr, rhs, reducedRhs_, threads);
  return true;
}

void ImplicitSchurComplement::multiply(const BlockSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd& y,
                                       int threads) {
  multiplyFree(system, x, y, threads);
  subtractEliminated(system, &x, x, y, threads);
}

template <int DI>
bool ImplicitSchurComplement::invertDiagonalBlock(const BlockSystem& system, bool withCouplings, int i) {
  using Square = Eigen::Matrix<double, DI, DI>;
  const int di = system.dim(i);
  Square d = BlockMap<DI, DI>(system.values(system.blocks()[system.diagonalBlock(i)]), di, di);
  if (withCouplings)
    for (Eigen::Index c = 0; c < diagonalPartials_.cols(); ++c)
      d += BlockMap<DI, DI>(diagonalPartials_.col(c).data() + diagonalOffsets_[i], di, di);
  Eigen::LLT<Square> llt(d);
  if (llt.info() != Eigen::Success) return false;
  Eigen::Map<Square>(diagonalInverses_.data() + diagonalOffsets_[i], di, di) = llt.solve(Square::Identity(di, di));
  return true;
}

bool ImplicitSchurComplement::invertDiagonalBlocks(const BlockSystem& system, bool withCouplings, int threads) {
  if (withCouplings) {
    // -W_il V_l^-1 W_il^T of every coupling, point by point into each chunk's blocks.
    diagonalPartials_.resize(static_cast<Eigen::Index>(diagonalInverses_.size()), partials_.cols());
    const auto& blocks = system.blocks();
    forEachChunk(
        system, threads,
        [&](int c, int l) {
          double* partial = diagonalPartials_.col(c).data();
          const int dl = system.dim(system.freeCount() + l);
          for (int k : marginalCouplings(system, l)) {
            const int i = blocks[k].row;
            subtractCongruence(system.values(blocks[k]), vInverses_.inverse(l), partial + diagonalOffsets_[i],
                               system.dim(i), dl);
          }
        },
        [&](int c) { diagonalPartials_.col(c).setZero(); });
  }
  std::vector<char> positive(system.freeCount(), 1);
  parallelFor(0, system.freeCount(), threads, 16, [&](int i) {
    positive[i] = system.dim(i) == 9   ? invertDiagonalBlock<9>(system, withCouplings, i)
                  : system.dim(i) == 6 ? invertDiagonalBlock<6>(system, withCouplings, i)
                                       : invertDiagonalBlock<Eigen::Dynamic>(system, withCouplings, i);
  });
  for (char p : positive)
    if (!p) return false;
  return true;
}

void ImplicitSchurComplement::applyDiagonalInverse(const BlockSystem& system, const Eigen::VectorXd& x,
                                                   Eigen::VectorXd& y) const {
  y.resize(x.size());
  for (int i = 0; i < system.freeCount(); ++i) {
    const int di = system.dim(i), offset = system.offset(i);
    y.segment(offset, di).noalias() =
        Eigen::Map<const Eigen::MatrixXd>(diagonalInverses_.data() + diagonalOffsets_[i], di, di) *
        x.segment(offset, di);
  }
}

}  // namespace lrsvo
