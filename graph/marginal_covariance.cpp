#include "lrsvo/graph/marginal_covariance.h"

#include <span>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include "lrsvo/graph/block_system.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

Eigen::MatrixXd marginalCovariance(Graph& graph, const std::vector<const Vertex*>& vertices,
                                   const std::vector<HeldCoordinate>& held) {
  BlockSystem system(graph, true);
  std::vector<int> targets;
  int size = 0;
  for (const Vertex* vertex : vertices) {
    const int block = system.blockOf(vertex);
    if (block < 0 || block >= system.freeCount())
      throw Error("covariance: vertex " + std::to_string(vertex->id()) +
                  " is fixed, marginalised or on no edge; expected a free vertex");
    targets.push_back(block);
    size += system.dim(block);
  }
  system.fill(1);
  for (const HeldCoordinate& h : held) {
    const int block = system.blockOf(h.vertex);
    if (block >= 0) system.holdCoordinate(block, h.coordinate);
  }

  // Reduced information S = U - sum_l W_l V_l^-1 W_l^T over the free vertices, lower triangle only
  // (the factorisation below reads no other).
  const int n = system.freeScalarCount();
  Eigen::MatrixXd reduced = Eigen::MatrixXd::Zero(n, n);
  for (const BlockSystem::Block& block : system.blocks()) {
    if (block.col >= system.freeCount()) continue;
    const Eigen::Map<const Eigen::MatrixXd> h(system.values(block), system.dim(block.row), system.dim(block.col));
    reduced.block(system.offset(block.col), system.offset(block.row), h.cols(), h.rows()) = h.transpose();
  }
  // Each marginalised vertex l at once: its free couplings stacked into W_l (rows in block order), so
  // the lower triangle of W_l V_l^-1 W_l^T is one product, scattered block by block.
  Eigen::MatrixXd w, product;
  std::vector<int> couplings;  // block ids of (i, l) with i free
  std::vector<int> at;         // each one's first row in W_l
  for (int l = system.freeCount(); l < system.blockCount(); ++l) {
    const std::span<const int> column = system.colBlocks(l);  // couplings (i, l), i < l, then the diagonal (l, l)
    const int dl = system.dim(l);
    couplings.clear();
    at.assign(1, 0);
    for (int id : column.first(column.size() - 1)) {
      const int row = system.blocks()[id].row;
      if (row >= system.freeCount()) continue;
      couplings.push_back(id);
      at.push_back(at.back() + system.dim(row));
    }
    if (couplings.empty()) continue;
    w.resize(at.back(), dl);
    for (std::size_t a = 0; a < couplings.size(); ++a)
      w.middleRows(at[a], at[a + 1] - at[a]) =
          Eigen::Map<const Eigen::MatrixXd>(system.values(system.blocks()[couplings[a]]), at[a + 1] - at[a], dl);
    const Eigen::Map<const Eigen::MatrixXd> v(system.values(system.blocks()[column.back()]), dl, dl);
    product.resize(w.rows(), w.rows());
    product.triangularView<Eigen::Lower>() = w * Eigen::LDLT<Eigen::MatrixXd>(v).solve(w.transpose());
    for (std::size_t b = 0; b < couplings.size(); ++b) {
      const int rowB = system.blocks()[couplings[b]].row, dimB = at[b + 1] - at[b];
      for (std::size_t a = 0; a < b; ++a) {
        const int rowA = system.blocks()[couplings[a]].row, dimA = at[a + 1] - at[a];
        reduced.block(system.offset(rowB), system.offset(rowA), dimB, dimA) -= product.block(at[b], at[a], dimB, dimA);
      }
      reduced.block(system.offset(rowB), system.offset(rowB), dimB, dimB).triangularView<Eigen::Lower>() -=
          product.block(at[b], at[b], dimB, dimB);
    }
  }

  const Eigen::LDLT<Eigen::MatrixXd> factor(reduced);
  if (factor.info() != Eigen::Success || !(factor.vectorD().array() > 0.0).all())
    throw Error("covariance: the information of the free vertices is singular (an unfixed gauge?)");
  // Columns of the inverse for the requested coordinates, then their rows.
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, size);
  for (int t = 0, column = 0; t < static_cast<int>(targets.size()); column += system.dim(targets[t++]))
    unit.block(system.offset(targets[t]), column, system.dim(targets[t]), system.dim(targets[t])).setIdentity();
  const Eigen::MatrixXd columns = factor.solve(unit);
  Eigen::MatrixXd covariance(size, size);
  for (int t = 0, row = 0; t < static_cast<int>(targets.size()); row += system.dim(targets[t++]))
    covariance.middleRows(row, system.dim(targets[t])) =
        columns.middleRows(system.offset(targets[t]), system.dim(targets[t]));
  return covariance;
}

}  // namespace lrsvo
