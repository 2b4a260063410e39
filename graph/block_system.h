#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "lrsvo/graph/graph.h"
#include "lrsvo/graph/large_array.h"

namespace lrsvo {

// The normal equations H dx = -g of a graph in block form, one block per
// pair of active (non-fixed) vertices that share an edge. Free vertices come
// first (block indices [0, freeCount)), marginalised ones after. The structure
// is built once per graph; fill() evaluates every edge and sums the blocks.
class BlockSystem {
 public:
  struct Block {
    int row;             // block index of the row vertex (row <= col)
    int col;             // block index of the column vertex
    std::size_t offset;  // start of the column-major row-dim x col-dim values
  };

  // schurOrdering: put marginalised vertices last (else treat all alike).
  BlockSystem(const Graph& graph, bool schurOrdering);

  // True when the graph has the structure this system was built for: the same
  // edges in the same order, on the same vertices, each as fixed, marginalised
  // and of the dimension it was. Such a graph may be solved on this system
  // (and a linear solver's analysis of it) again: O(edges), no allocation.
  bool describes(const Graph& graph, bool schurOrdering) const;

  int blockCount() const { return static_cast<int>(vertices_.size()); }
  int freeCount() const { return freeCount_; }
  int dim(int block) const { return dims_[block]; }
  int offset(int block) const { return offsets_[block]; }
  int scalarCount() const { return scalarCount_; }
  int freeScalarCount() const { return blockCount() == freeCount_ ? scalarCount_ : offsets_[freeCount_]; }
  Vertex* vertex(int block) const { return vertices_[block]; }
  // Block index of a vertex, or -1 when it is fixed or on no edge.
  int blockOf(const Vertex* vertex) const;

  // The diagonal block of vertex i is block i; the others follow column by
  // column, each column's by row (the order of the Schur solvers' passes).
  const std::vector<Block>& blocks() const { return blocks_; }
  // Blocks of row r (columns >= r), sorted by column; the first is the diagonal.
  std::span<const int> rowBlocks(int row) const { return slice(rowBlockIds_, rowStart_, row); }
  // Blocks of column c (rows <= c), sorted by row; the last is the diagonal.
  // Their values lie one after another in that order (column-major blocks,
  // each rows x cols), so a marginalised vertex's couplings and its diagonal
  // block are one contiguous stretch.
  std::span<const int> colBlocks(int col) const { return slice(colBlockIds_, colStart_, col); }
  int diagonalBlock(int block) const { return block; }
  double* values(const Block& block) { return values_.data() + block.offset; }
  const double* values(const Block& block) const { return values_.data() + block.offset; }
  // Every block's values; block b's start at valueData() + b.offset.
  const double* valueData() const { return values_.data(); }

  const Eigen::VectorXd& gradient() const { return gradient_; }
  // Undamped diagonal of H.
  const Eigen::VectorXd& diagonal() const { return diagonal_; }

  // Linearises every edge, fills H and g; returns the total cost.
  double fill(int threads);
  // Total cost at the current estimates without derivatives.
  double cost(int threads) const;
  // Sets diag(H) = undamped diagonal + shift.
  void setDiagonalShift(const Eigen::VectorXd& shift);
  // Holds one coordinate of an active vertex: its row and column of H become
  // those of the identity and its gradient zero, so every solve gives it a
  // zero step (active-set methods). Undone by the next fill().
  void holdCoordinate(int block, int coordinate);
  // y = H x with the current (possibly shifted) blocks.
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;
  // The right-hand side of geodesic acceleration: the sum over edges of
  // J_e^T r''_e, r''_e the second derivative of edge e's residual along dx by
  // finite differences with step h (Edge::addSecondDirectionalGradient), zero
  // at held coordinates. After fill(); the estimates are left as they were.
  Eigen::VectorXd secondDirectionalGradient(const Eigen::VectorXd& dx, double h);

  // Applies x <- x [+] dx to every active vertex.
  void applyStep(const Eigen::VectorXd& dx);
  // Saves and restores all active vertex estimates (for rejected steps).
  void saveEstimates();
  void restoreEstimates();

 private:
  struct Contribution {
    Edge* edge;
    int a;  // the edge's local index of the row vertex
    int b;  // the edge's local index of the column vertex
  };

  // A free-free block's share from an edge on a marginalised vertex: summed in
  // that vertex's column pass, while the edge is in cache, into the partial
  // sums of the vertex's range of columns.
  struct CarriedContribution {
    Edge* edge;
    int block;
    std::int16_t a;  // the edge's local indices of the row and column vertices (16 bytes in all)
    std::int16_t b;
  };

  // Sums block k of H from its edges; a diagonal block also its gradient and diagonal.
  void fillBlock(int k);
  // Splits the marginalised columns into ranges of about equal work, as many
  // as pay for their partial sums (at most kMaxCarriedRanges), fixed by the
  // structure alone so that sums do not depend on the thread count.
  void splitMarginalisedColumns();
  // The marginalised columns of range r: their blocks, and their carried
  // contributions summed into the range's partial sums.
  void fillMarginalisedRange(int r);
  double* partialSums(int range) { return partialSums_.data() + static_cast<std::size_t>(range) * partialSize_; }
  // Entries [start[i], start[i + 1]) of a list stored by rows (CSR).
  template <typename Items>
  static std::span<const typename Items::value_type> slice(const Items& items, const std::vector<std::size_t>& start,
                                                           int i) {
    return {items.data() + start[i], start[i + 1] - start[i]};
  }

  bool schurOrdering_;
  std::vector<Edge*> edges_;
  // Per edge in graph order: its vertex count, then its vertices' blocks (-1: fixed).
  LargeArray<int> edgeVertexBlocks_;
  std::vector<Vertex*> vertices_;
  std::unordered_map<const Vertex*, int> blockIndex_;
  std::vector<int> dims_, offsets_;
  int freeCount_ = 0;
  int scalarCount_ = 0;
  std::vector<Block> blocks_;
  std::vector<std::size_t> rowStart_, colStart_;  // CSR of the blocks by row and by column
  std::vector<int> rowBlockIds_, colBlockIds_;
  std::vector<std::size_t> contributionStart_;  // CSR of each block's edges, in edge order
  LargeArray<Contribution> contributions_;
  LargeArray<double> values_;
  Eigen::VectorXd gradient_, diagonal_;
  std::vector<int> heldScalars_;  // since the last fill()
  std::vector<double> savedEstimates_;
  std::vector<std::size_t> estimateOffsets_;
  // Free-free blocks come first in values_ (the layout is by column, free
  // columns first): their values are [0, freeValueCount_).
  std::size_t freeValueCount_ = 0;
  std::vector<std::size_t> carriedStart_;  // CSR by marginalised column
  LargeArray<CarriedContribution> carried_;
  std::vector<int> marginalisedRanges_;  // bounds of the ranges of marginalised columns
  // Per range: the free-free values, then the free gradient.
  std::size_t partialSize_ = 0;
  std::vector<double> partialSums_;
};

}  // namespace lrsvo
