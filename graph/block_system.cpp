#include "lrsvo/graph/block_system.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "lrsvo/graph/block_kernels.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/parallel_for.h"
#include "lrsvo/graph/vertex_positions.h"

namespace lrsvo {

namespace {

// Active vertices (non-fixed, on at least one edge) in graph order, free ones
// first when the Schur ordering is asked for.
std::vector<Vertex*> orderVertices(const Graph& graph, const VertexPositions& positions, bool schurOrdering,
                                   int* freeCount) {
  std::vector<char> used(graph.vertices().size(), 0);
  for (const auto& edge : graph.edges())
    for (const Vertex* v : edge->vertices()) {
      const int position = positions.find(v);
      if (position >= 0 && !v->fixed()) used[static_cast<std::size_t>(position)] = 1;
    }
  std::vector<Vertex*> free, marginalised;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    Vertex* v = graph.vertices()[i].get();
    (schurOrdering && v->marginalized() ? marginalised : free).push_back(v);
  }
  *freeCount = static_cast<int>(free.size());
  free.insert(free.end(), marginalised.begin(), marginalised.end());
  return free;
}

// Stable sort of a short range by key: insertion sort where std::stable_sort
// would allocate a buffer for a handful of items.
template <typename Iterator, typename Key>
void stableSortBy(Iterator first, Iterator last, const Key& key) {
  if (last - first > 32) {
    std::stable_sort(first, last, [&](const auto& x, const auto& y) { return key(x) < key(y); });
    return;
  }
  for (Iterator i = first + 1; i < last; ++i) {
    auto item = *i;
    Iterator j = i;
    for (; j > first && key(*(j - 1)) > key(item); --j) *j = *(j - 1);
    *j = item;
  }
}

// One pair (row <= col) of an edge's active vertices, in its column's list.
struct PairSlot {
  int row;
  Edge* edge;
  int a;  // the edge's local index of the row vertex
  int b;  // the edge's local index of the column vertex
};

// Calls visit(row, col, edge, a, b) for every pair of an edge's active
// vertices with row <= col, edge by edge in graph order.
template <typename Visit>
void forEachPair(const Graph& graph, const VertexPositions& positions, const std::vector<int>& blockOfPosition,
                 const Visit& visit) {
  std::vector<int> edgeBlocks;  // block of each of an edge's vertices, -1 if inactive
  for (const auto& edgePtr : graph.edges()) {
    Edge* edge = edgePtr.get();
    const int n = edge->vertexCount();
    edgeBlocks.assign(static_cast<std::size_t>(n), -1);
    for (int a = 0; a < n; ++a) {
      const int position = positions.find(edge->vertex(a));
      if (position >= 0) edgeBlocks[static_cast<std::size_t>(a)] = blockOfPosition[static_cast<std::size_t>(position)];
    }
    for (int a = 0; a < n; ++a) {
      const int row = edgeBlocks[static_cast<std::size_t>(a)];
      if (row < 0) continue;
      for (int b = 0; b < n; ++b) {
        const int col = edgeBlocks[static_cast<std::size_t>(b)];
        if (col >= 0 && row <= col) visit(row, col, edge, a, b);
      }
    }
  }
}

// Every pair, bucketed by column in two passes over the edges (count, then
// place) and sorted by row within its column, each pair's edges in edge order
// (the order H's blocks sum them in): no list of all pairs is sorted or
// copied. columnStart gets the buckets' bounds (CSR).
LargeArray<PairSlot> pairsByColumn(const Graph& graph, const VertexPositions& positions,
                                   const std::vector<int>& blockOfPosition, int blockCount,
                                   std::vector<std::size_t>* columnStart) {
  std::vector<std::size_t>& start = *columnStart;
  start.assign(static_cast<std::size_t>(blockCount) + 1, 0);
  forEachPair(graph, positions, blockOfPosition, [&](int row, int col, const Edge* edge, int a, int b) {
    if (row == col && a != b)
      throw Error(std::string("edge ") + edge->typeTag() + " names vertex " + std::to_string(edge->vertex(a)->id()) +
                  " twice");
    ++start[static_cast<std::size_t>(col) + 1];
  });
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  LargeArray<PairSlot> slots(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  forEachPair(graph, positions, blockOfPosition, [&](int row, int col, Edge* edge, int a, int b) {
    slots[next[static_cast<std::size_t>(col)]++] = PairSlot{row, edge, a, b};
  });
  for (std::size_t c = 0; c + 1 < start.size(); ++c)
    stableSortBy(slots.begin() + static_cast<std::ptrdiff_t>(start[c]),
                 slots.begin() + static_cast<std::ptrdiff_t>(start[c + 1]),
                 [](const PairSlot& slot) { return slot.row; });
  return slots;
}

}  // namespace

BlockSystem::BlockSystem(const Graph& graph, bool schurOrdering) {
  if (graph.empty()) throw Error("optimise: the graph has no vertices");
  if (graph.edges().empty()) throw Error("optimise: the graph has no edges");
  std::vector<const Vertex*> graphVertices;
  graphVertices.reserve(graph.vertices().size());
  for (const auto& v : graph.vertices()) graphVertices.push_back(v.get());
  const VertexPositions positions(graphVertices);
  vertices_ = orderVertices(graph, positions, schurOrdering, &freeCount_);
  if (vertices_.empty()) throw Error("optimise: every vertex on an edge is fixed; nothing to optimise");

  // The block of each graph position, -1 for fixed vertices and those on no edge.
  std::vector<int> blockOfPosition(graphVertices.size(), -1);
  blockIndex_.reserve(vertices_.size());
  for (int i = 0; i < blockCount(); ++i) {
    blockIndex_[vertices_[i]] = i;
    blockOfPosition[static_cast<std::size_t>(positions.find(vertices_[i]))] = i;
    dims_.push_back(vertices_[i]->dimension());
    offsets_.push_back(scalarCount_);
    scalarCount_ += dims_.back();
  }

  edges_.reserve(graph.edges().size());
  for (const auto& edge : graph.edges()) edges_.push_back(edge.get());
  std::vector<std::size_t> columnStart;
  LargeArray<PairSlot> slots = pairsByColumn(graph, positions, blockOfPosition, blockCount(), &columnStart);

  // Block ids: the diagonal of vertex i is block i, the others follow column
  // by column, row by row (a column's diagonal, row == col, ends it);
  // colBlockIds_ lists every block in that order. The contributions go by
  // block id: the diagonals' first, in column order, then the others in the
  // order of the walk.
  for (int i = 0; i < blockCount(); ++i) blocks_.push_back(Block{i, i, 0});
  rowStart_.assign(blockCount() + 1, 0);
  colStart_.assign(blockCount() + 1, 0);
  // Each block's contribution count at [id + 1], summed into the starts below.
  contributionStart_.assign(static_cast<std::size_t>(blockCount()) + 1, 0);
  for (int c = 0; c < blockCount(); ++c) {
    const auto first = slots.begin() + static_cast<std::ptrdiff_t>(columnStart[static_cast<std::size_t>(c)]);
    const auto last = slots.begin() + static_cast<std::ptrdiff_t>(columnStart[static_cast<std::size_t>(c) + 1]);
    for (auto slot = first; slot != last; ++slot) {
      const bool newPair = slot == first || slot->row != (slot - 1)->row;
      if (slot->row == c) {
        ++contributionStart_[static_cast<std::size_t>(c) + 1];
      } else if (newPair) {
        blocks_.push_back(Block{slot->row, c, 0});
        contributionStart_.push_back(1);
      } else {
        ++contributionStart_.back();
      }
      if (newPair) {
        colBlockIds_.push_back(slot->row == c ? c : static_cast<int>(blocks_.size()) - 1);
        ++rowStart_[slot->row + 1];
        ++colStart_[c + 1];
      }
    }
  }
  for (int i = 0; i < blockCount(); ++i) {
    rowStart_[i + 1] += rowStart_[i];
    colStart_[i + 1] += colStart_[i];
  }
  for (std::size_t k = 0; k < blocks_.size(); ++k) contributionStart_[k + 1] += contributionStart_[k];
  contributions_.resize(slots.size());
  // The diagonals' contributions fill [0, start of the first other block).
  std::size_t nextDiagonal = 0, nextOther = contributionStart_[static_cast<std::size_t>(blockCount())];
  for (int c = 0; c < blockCount(); ++c)
    for (std::size_t e = columnStart[static_cast<std::size_t>(c)]; e < columnStart[static_cast<std::size_t>(c) + 1];
         ++e)
      contributions_[slots[e].row == c ? nextDiagonal++ : nextOther++] = {slots[e].edge, slots[e].a, slots[e].b};
  // Released before H's values are allocated, so the set-up's peak memory is
  // the larger of the two, not their sum.
  LargeArray<PairSlot>().swap(slots);

  // Each row's blocks listed by column.
  rowBlockIds_.resize(colBlockIds_.size());
  std::vector<std::size_t> nextInRow(rowStart_.begin(), rowStart_.end() - 1);
  for (int id : colBlockIds_)
    rowBlockIds_[nextInRow[static_cast<std::size_t>(blocks_[static_cast<std::size_t>(id)].row)]++] = id;
  // Values laid out by column, then row: a marginalised vertex's couplings and
  // its diagonal block are contiguous, for the Schur solvers' point-by-point
  // passes and fill()'s column-by-column sums.
  std::size_t size = 0;
  for (int id : colBlockIds_) {
    Block& block = blocks_[static_cast<std::size_t>(id)];
    block.offset = size;
    size += static_cast<std::size_t>(dims_[block.row]) * dims_[block.col];
  }
  values_.assign(size, 0.0);
  gradient_ = Eigen::VectorXd::Zero(scalarCount_);
  diagonal_ = Eigen::VectorXd::Zero(scalarCount_);
}

int BlockSystem::blockOf(const Vertex* vertex) const {
  auto it = blockIndex_.find(vertex);
  return it == blockIndex_.end() ? -1 : it->second;
}

double BlockSystem::fill(int threads) {
  const int edgeCount = static_cast<int>(edges_.size());
  std::vector<double> costs(edgeCount);
  parallelFor(0, edgeCount, threads, [&](int e) { costs[e] = edges_[e]->linearize(); });

  // Column by column: the blocks of one column share their edges (a point's
  // W blocks and its V block), so each edge is read from memory once per
  // column and found in cache for the column's other blocks.
  parallelFor(0, blockCount(), threads, [&](int column) {
    for (int k : colBlocks(column)) fillBlock(k);
  });

  heldScalars_.clear();
  double total = 0.0;
  for (double c : costs) total += c;
  return total;
}

void BlockSystem::fillBlock(int k) {
  const Block& block = blocks_[k];
  double* target = values(block);
  const int rows = dims_[block.row];
  std::fill(target, target + rows * dims_[block.col], 0.0);
  const std::span<const Contribution> edges = slice(contributions_, contributionStart_, k);
  if (k >= blockCount()) {
    for (const Contribution& c : edges) c.edge->addHessianBlock(c.a, c.b, target, rows);
    return;
  }
  // Diagonal block k: the edges on vertex k, which also make its gradient,
  // taken while each edge is in cache.
  double* g = gradient_.data() + offsets_[k];
  std::fill(g, g + rows, 0.0);
  for (const Contribution& c : edges) {
    c.edge->addHessianBlock(c.a, c.a, target, rows);
    c.edge->addGradient(c.a, g);
  }
  for (int d = 0; d < rows; ++d) diagonal_[offsets_[k] + d] = target[d * rows + d];
}

double BlockSystem::cost(int threads) const {
  const int edgeCount = static_cast<int>(edges_.size());
  std::vector<double> costs(edgeCount);
  parallelFor(0, edgeCount, threads, [&](int e) { costs[e] = edges_[e]->cost(); });
  double total = 0.0;
  for (double c : costs) total += c;
  return total;
}

void BlockSystem::setDiagonalShift(const Eigen::VectorXd& shift) {
  for (int i = 0; i < blockCount(); ++i) {
    double* diag = values(blocks_[diagonalBlock(i)]);
    for (int d = 0; d < dims_[i]; ++d) diag[d * dims_[i] + d] = diagonal_[offsets_[i] + d] + shift[offsets_[i] + d];
  }
}

void BlockSystem::holdCoordinate(int block, int coordinate) {
  const int d = dims_[block];
  for (int k : rowBlocks(block)) {
    const int cols = dims_[blocks_[k].col];
    for (int c = 0; c < cols; ++c) values(blocks_[k])[c * d + coordinate] = 0.0;
  }
  for (int k : colBlocks(block)) {
    const int rows = dims_[blocks_[k].row];
    std::fill_n(values(blocks_[k]) + coordinate * rows, rows, 0.0);
  }
  values(blocks_[diagonalBlock(block)])[coordinate * d + coordinate] = 1.0;
  diagonal_[offsets_[block] + coordinate] = 1.0;
  gradient_[offsets_[block] + coordinate] = 0.0;
  heldScalars_.push_back(offsets_[block] + coordinate);
}

Eigen::VectorXd BlockSystem::multiply(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(scalarCount_);
  for (const Block& block : blocks_) {
    const int rows = dims_[block.row], cols = dims_[block.col];
    kernels::accumulateBlock<false>(values(block), x.data() + offsets_[block.col], y.data() + offsets_[block.row], rows,
                                    cols, 1.0);
    if (block.row != block.col)
      kernels::accumulateBlock<true>(values(block), x.data() + offsets_[block.row], y.data() + offsets_[block.col],
                                     rows, cols, 1.0);
  }
  return y;
}

Eigen::VectorXd BlockSystem::secondDirectionalGradient(const Eigen::VectorXd& dx, double h) {
  saveEstimates();
  applyStep(h * dx);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(scalarCount_);
  std::vector<const double*> steps;
  std::vector<double*> gradients;
  for (const Edge* edge : edges_) {
    steps.assign(edge->vertexCount(), nullptr);
    gradients.assign(edge->vertexCount(), nullptr);
    for (int k = 0; k < edge->vertexCount(); ++k) {
      const int block = blockOf(edge->vertex(k));
      if (block < 0) continue;
      steps[k] = dx.data() + offsets_[block];
      gradients[k] = sum.data() + offsets_[block];
    }
    edge->addSecondDirectionalGradient(h, steps.data(), gradients.data());
  }
  restoreEstimates();
  for (int scalar : heldScalars_) sum[scalar] = 0.0;
  return sum;
}

void BlockSystem::applyStep(const Eigen::VectorXd& dx) {
  for (int i = 0; i < blockCount(); ++i) vertices_[i]->oplus(dx.data() + offsets_[i]);
}

void BlockSystem::saveEstimates() {
  if (estimateOffsets_.empty()) {
    std::size_t size = 0;
    for (Vertex* v : vertices_) {
      estimateOffsets_.push_back(size);
      size += v->estimateSize();
    }
    savedEstimates_.resize(size);
  }
  for (int i = 0; i < blockCount(); ++i) vertices_[i]->getEstimate(savedEstimates_.data() + estimateOffsets_[i]);
}

void BlockSystem::restoreEstimates() {
  for (int i = 0; i < blockCount(); ++i) vertices_[i]->setEstimate(savedEstimates_.data() + estimateOffsets_[i]);
}

}  // namespace lrsvo
