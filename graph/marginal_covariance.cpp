#include "lrsvo/graph/marginal_covariance.h"

#include <string>

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

  // Reduced information S = U - sum_l W_l V_l^-1 W_l^T over the free vertices.
  const int n = system.freeScalarCount();
  Eigen::MatrixXd reduced = Eigen::MatrixXd::Zero(n, n);
  for (const BlockSystem::Block& block : system.blocks()) {
    if (block.col >= system.freeCount()) continue;
    const Eigen::Map<const Eigen::MatrixXd> h(system.values(block), system.dim(block.row), system.dim(block.col));
    reduced.block(system.offset(block.row), system.offset(block.col), h.rows(), h.cols()) = h;
    if (block.row != block.col)
      reduced.block(system.offset(block.col), system.offset(block.row), h.cols(), h.rows()) = h.transpose();
  }
  for (int l = system.freeCount(); l < system.blockCount(); ++l) {
    const std::span<const int> column = system.colBlocks(l);  // couplings (i, l), i < l, then the diagonal (l, l)
    const int dl = system.dim(l);
    const Eigen::Map<const Eigen::MatrixXd> v(system.values(system.blocks()[column.back()]), dl, dl);
    const Eigen::LDLT<Eigen::MatrixXd> vInverse(v);
    for (int a : column) {
      const BlockSystem::Block& wa = system.blocks()[a];
      if (wa.row >= system.freeCount()) continue;
      const Eigen::Map<const Eigen::MatrixXd> wRowA(system.values(wa), system.dim(wa.row), dl);
      const Eigen::MatrixXd y = vInverse.solve(wRowA.transpose());  // V^-1 W_a^T
      for (int b : column) {
        const BlockSystem::Block& wb = system.blocks()[b];
        if (wb.row >= system.freeCount()) continue;
        const Eigen::Map<const Eigen::MatrixXd> wRowB(system.values(wb), system.dim(wb.row), dl);
        reduced.block(system.offset(wb.row), system.offset(wa.row), wRowB.rows(), y.cols()) -= wRowB * y;
      }
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
